# Build speed: a cold build of the program and the test suite on 2 cores.
#
# Release without debug information. Debian's deal.II exports its own
# package-build flags (-g among them) in DEAL_II_CXX_FLAGS; debug information
# for these template-heavy translation units costs about a third of each
# compile and most of each link. Debug builds keep theirs (-ggdb).
if(CMAKE_BUILD_TYPE STREQUAL "Release")
  string(REGEX REPLACE "(^| )-g( |$)" " " DEAL_II_CXX_FLAGS "${DEAL_II_CXX_FLAGS}")
endif()

# The deal.II and Trilinos headers that most translation units include,
# precompiled once by hyperelastic_core and reused by every other target
# (hyperelastic_setup_target): parsing them was half of each compile.
set(HYPERELASTIC_PRECOMPILED_HEADERS
  <deal.II/base/bounding_box.h>
  <deal.II/base/conditional_ostream.h>
  <deal.II/base/data_out_base.h>
  <deal.II/base/exceptions.h>
  <deal.II/base/function.h>
  <deal.II/base/function_parser.h>
  <deal.II/base/index_set.h>
  <deal.II/base/mpi.h>
  <deal.II/base/numbers.h>
  <deal.II/base/parameter_handler.h>
  <deal.II/base/point.h>
  <deal.II/base/quadrature.h>
  <deal.II/base/quadrature_lib.h>
  <deal.II/base/symmetric_tensor.h>
  <deal.II/base/tensor.h>
  <deal.II/base/timer.h>
  <deal.II/base/types.h>
  <deal.II/base/utilities.h>
  <deal.II/distributed/fully_distributed_tria.h>
  <deal.II/dofs/dof_handler.h>
  <deal.II/dofs/dof_tools.h>
  <deal.II/fe/fe.h>
  <deal.II/fe/fe_simplex_p.h>
  <deal.II/fe/fe_system.h>
  <deal.II/fe/fe_values.h>
  <deal.II/fe/fe_values_extractors.h>
  <deal.II/fe/mapping.h>
  <deal.II/fe/mapping_fe.h>
  <deal.II/grid/grid_tools.h>
  <deal.II/grid/tria.h>
  <deal.II/grid/tria_description.h>
  <deal.II/lac/affine_constraints.h>
  <deal.II/lac/dynamic_sparsity_pattern.h>
  <deal.II/lac/full_matrix.h>
  <deal.II/lac/solver_cg.h>
  <deal.II/lac/solver_control.h>
  <deal.II/lac/sparsity_tools.h>
  <deal.II/lac/trilinos_precondition.h>
  <deal.II/lac/trilinos_sparse_matrix.h>
  <deal.II/lac/trilinos_vector.h>
  <deal.II/lac/vector.h>
  <deal.II/numerics/data_out.h>
  <deal.II/numerics/rtree.h>
  <deal.II/numerics/vector_tools.h>
  <array>
  <cmath>
  <map>
  <memory>
  <string>
  <vector>
  )

# deal.II's flags and include directories for <target>, and the precompiled
# headers of hyperelastic_core (which builds them).
function(hyperelastic_setup_target target)
  deal_ii_setup_target(${target})
  if(target STREQUAL "hyperelastic_core")
    target_precompile_headers(${target} PRIVATE ${HYPERELASTIC_PRECOMPILED_HEADERS})
  else()
    target_precompile_headers(${target} REUSE_FROM hyperelastic_core)
  endif()
endfunction()
