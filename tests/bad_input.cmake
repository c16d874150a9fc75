# The bad-input contract (README, "Exit codes"), one test per class of input
# that once crashed, hung or lied: one line naming the file, the parameter
# and what was expected, exit 1 (a solver that fails: exit 2 with its
# summary.json), nothing overwritten. Inputs: tests/data/bad/.
set(BAD tests/data/bad)

# A line of a million commas: read in one pass (it took more than a minute).
add_test(NAME error/abaqus_million_commas
  COMMAND bash -c "mkdir -p $1 && { echo '*Node'; printf '1'; head -c 1000000 /dev/zero | tr '\\\\0' ','; echo; } > $1/commas.inp && $0 $2 $1/run 1 'commas.inp: Mesh/File: line 2' --set Mesh/File=$1/commas.inp prm/column.prm"
    ${RUN_ERROR} ${OUT}/error_abaqus_million_commas_input $<TARGET_FILE:restshape>
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})

add_test(NAME run/hinged_piece_named
  COMMAND bash -c "$0 prm/column.prm --set Output/Directory=$1 --set Mesh/File=tests/data/bad/hinged_piece.msh > $1.log && grep -E 'Warning: a piece of 120 cells \\(label 3\\) around .* mm hinges about the edge joining it to the held body' $1.log"
    $<TARGET_FILE:restshape> ${OUT}/run_hinged_piece
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})

# Control bytes of a file name reach the terminal escaped.
add_test(NAME error/control_bytes_escaped
  COMMAND bash -c "$0 $2 $1 1 'a.x01.x1b.31mb.msh: Mesh/File: no such file' --set \"Mesh/File=$(printf 'a\\001\\033[31mb.msh')\" prm/column.prm"
    ${RUN_ERROR} ${OUT}/error_control_bytes_escaped $<TARGET_FILE:restshape>
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
# A number below the smallest normal double is a number.
add_test(NAME run/subnormal_gravity_component
  COMMAND bash -c "$0 prm/column.prm --set Output/Directory=$1 --set 'Loads/Gravity=1e-308, 0, -9.81' --set 'Solver/Check stability=false' > /dev/null && grep -q '\"converged\": true' $1/summary.json"
    $<TARGET_FILE:restshape> ${OUT}/run_subnormal_gravity
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})

# The same contract on 2 ranks.
function(restshape_mpi_error_test name code regex)
  add_test(NAME mpi/error_${name}
    COMMAND ${CMAKE_COMMAND} -E env MPI_RANKS=2
      ${RUN_ERROR} $<TARGET_FILE:restshape> ${OUT}/mpi_error_${name} ${code} ${regex} ${ARGN}
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(mpi/error_${name} PROPERTIES PROCESSORS 2)
endfunction()
restshape_mpi_error_test(gravity_overflows 1 "Loads/Gravity, Materials/Density: the strain"
  --set "Loads/Gravity=1e300, 0, 0" prm/column.prm)
restshape_mpi_error_test(floating_piece 1 "floats freely"
  --set Mesh/File=${BAD}/floating_piece.msh prm/column.prm)
restshape_mpi_error_test(vtk_huge_cells 1 "vtk_huge_cells.vtk: Mesh/File: CELLS declares"
  --set Mesh/File=${BAD}/vtk_huge_cells.vtk prm/column.prm)

# The mesher.
restshape_mesher_error_test(skull_gap_too_deep
  "--skull-gap: a skull 20 mm inside the labelled region's surface encloses nothing of it"
  --image tests/data/sphere_labels.nii --out @OUT@/mesh.msh --skull-out @OUT@/skull.off --skull-gap -20)
restshape_mesher_error_test(skull_gap_too_wide
  "--skull-gap: a gap of 1e\\+06 mm needs a distance grid of"
  --image tests/data/sphere_labels.nii --out @OUT@/mesh.msh --skull-out @OUT@/skull.off --skull-gap 1e6)
restshape_mesher_error_test(skull_bad_extension
  "skull.ply: --skull-out: unsupported extension '.ply'. expected a surface file name"
  --image tests/data/sphere_labels.nii --out @OUT@/mesh.msh --skull-out @OUT@/skull.ply --skull-gap 1)
restshape_mesher_error_test(out_is_a_directory
  "--out: is a directory. expected a gmsh file name"
  --image tests/data/sphere_labels.nii --out @OUT@)
restshape_mesher_error_test(cell_size_below_voxel
  "sphere_labels.nii: --cell-size: 0.01 mm is far below the voxel size \\(2 mm\\). expected at least 0.5 mm"
  --image tests/data/sphere_labels.nii --out @OUT@/mesh.msh --cell-size 0.01)
restshape_mesher_error_test(facet_distance_below_voxel
  "--facet-distance: 0.001 mm is far below the voxel size"
  --image tests/data/sphere_labels.nii --out @OUT@/mesh.msh --facet-distance 0.001)
restshape_mesher_error_test(skull_facet_size_below_voxel
  "--skull-facet-size: 0.001 mm is far below the voxel size"
  --image tests/data/sphere_labels.nii --out @OUT@/mesh.msh --skull-out @OUT@/skull.off
  --skull-gap 1 --skull-facet-size 0.001)
foreach(name voxel_1e-30 voxel_1e30)
  restshape_mesher_error_test(${name} "${name}.nii: --image: a voxel size of 1e.30 mm in the header"
    --image ${BAD}/${name}.nii --out @OUT@/mesh.msh)
endforeach()
restshape_mesher_error_test(nifti_dim0_zero "dim0_zero.nii: --image: the image has dimensions"
  --image ${BAD}/dim0_zero.nii --out @OUT@/mesh.msh)
restshape_mesher_error_test(sform_nan_offset
  "sform_nan_offset.nii: --image: the header puts the image's origin at nan mm"
  --image ${BAD}/sform_nan_offset.nii --out @OUT@/mesh.msh)
restshape_mesher_error_test(qform_huge_offset
  "qform_huge_offset.nii: --image: the header puts the image's origin at 1e\\+30 mm"
  --image ${BAD}/qform_huge_offset.nii --out @OUT@/mesh.msh)

# Interrupted runs leave the old result or the new one, never a mix.
add_test(NAME run/interrupted_runs
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/run_interrupts.sh $<TARGET_FILE:restshape> ${OUT}/interrupted_runs
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})

# An MPI run interrupted (SIGTERM to mpirun, and to the ranks): every rank
# ends, summary.json and one line say so, no temporary file.
add_test(NAME mpi/interrupted_run
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/run_mpi_interrupt.sh $<TARGET_FILE:restshape> ${OUT}/mpi_interrupted_run
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})

# A disk that fills during the run: exit 5, one line, partial files removed.
add_test(NAME run/disk_full
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/run_disk_full.sh $<TARGET_FILE:restshape> ${OUT}/disk_full
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(run/disk_full PROPERTIES SKIP_RETURN_CODE 77)

# Runs started side by side all initialise MPI.
add_test(NAME run/concurrent_starts
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/run_concurrent_starts.sh $<TARGET_FILE:restshape> ${OUT}/concurrent_starts
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
