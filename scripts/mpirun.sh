#!/usr/bin/env bash
# mpirun that also works as root (CI, containers): Open MPI refuses root
# unless told otherwise.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
exec mpirun --oversubscribe "$@"
