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

# Unity builds (as ASPECT's ASPECT_UNITY_BUILD): the source files of each
# folder of source/ (one concern each) compiled as one translation unit, so
# that the templates, inline functions and vtables of the headers that the
# folder's files share are instantiated and optimized once per folder rather
# than once per file (about 5 s of every small unit's compile was that
# repeated work). OFF compiles every file on its own (a clash of file-local
# names across a folder shows only with ON: give such helpers distinct names).
option(HYPERELASTIC_UNITY_BUILD
  "Compile the files of each source/ folder as one translation unit" ON)

# The files that stay units of their own: the second files of a class split
# over two (its 'template class X<2>;' instantiates the members defined in
# each file, and two of them in one unit are a duplicate instantiation).
set(HYPERELASTIC_OWN_UNITS
  source/contact/obstacle_geometry.cc
  source/contact/mesh_obstacle_geometry.cc
  source/contact/self_contact_boundary.cc
  )

# The folder whose unit does not use the precompiled headers, so that it
# compiles on the second core during the minute the first precompiles them
# (every other unit waits for them): the largest, mesh/ (about 2 minutes).
set(HYPERELASTIC_UNIT_BESIDE_PCH mesh)

# hyperelastic_unity_by_folder(<target> <source>...): <target>'s sources
# grouped into one unity unit per folder (HYPERELASTIC_OWN_UNITS apart).
function(hyperelastic_unity_by_folder target)
  if(NOT HYPERELASTIC_UNITY_BUILD)
    return()
  endif()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON
    UNITY_BUILD_MODE GROUP)
  foreach(source ${ARGN})
    if(source IN_LIST HYPERELASTIC_OWN_UNITS)
      set_source_files_properties(${source} TARGET_DIRECTORY ${target}
        PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
      continue()
    endif()
    get_filename_component(folder ${source} DIRECTORY)
    get_filename_component(folder ${folder} NAME)
    set_source_files_properties(${source} TARGET_DIRECTORY ${target}
      PROPERTIES UNITY_GROUP ${folder})
  endforeach()
  # The unit that compiles while the headers are precompiled (CMake names
  # a group's unit unity_<group>_cxx.cxx): it parses its headers itself.
  set_source_files_properties(
    ${CMAKE_CURRENT_BINARY_DIR}/CMakeFiles/${target}.dir/Unity/unity_${HYPERELASTIC_UNIT_BESIDE_PCH}_cxx.cxx
    TARGET_DIRECTORY ${target} PROPERTIES SKIP_PRECOMPILE_HEADERS ON)
endfunction()
