# tests/distributed: the job runner (linked with fm_distributed), and the runs over MPI with
# 1, 2 and 3 ranks (mpi_runs_test.sh: the runner's tests under mpirun, and evaluate's CSV
# byte-identical for every rank count). The script skips (77) only when MPI was not built.
target_link_libraries(fm_test_${name} PRIVATE fm_distributed)
if(TARGET fluoromatch)
    add_test(NAME distributed_mpi_runs
        COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/mpi_runs_test.sh "${FM_MPI_FOUND}" "${FM_MPIEXEC}"
                $<TARGET_FILE:fm_test_${name}> $<TARGET_FILE:fluoromatch>
                ${PROJECT_SOURCE_DIR}/distributed/lsan-openmpi.supp)
    # COST: a fresh build (CI) has no timing history, and ctest then started this, a long test
    # (22 s in Release, 143-236 s under the sanitizers), last: the other core idled while it ran.
    set_tests_properties(distributed_mpi_runs PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 600
                         COST 200)
    # 3 ranks there, against one process (3 has every path 2 has, and rank 0 working alone is
    # Release's 1-rank run; each rank count ~40 s of CPU under the sanitizers).
    # Heavy there (~190 s): left out of the quick sanitizer pass (scripts/test --skip-heavy).
    if(FM_SANITIZE)
        set_tests_properties(distributed_mpi_runs PROPERTIES ENVIRONMENT "FM_MPI_RANKS=3" LABELS heavy)
    endif()
endif()
