# CTest script for bench_report: the machine line, the table's format (medians of three runs with
# each run's value), its verdicts and exit status on fixtures, and that bench/targets.json reads.
# Run as cmake -DREPORT=<bench_report> -DDATA=<this folder> -DTARGETS=<bench/targets.json>
# -P check-report.cmake.
function(report targets results out_status out_text)
    execute_process(COMMAND ${REPORT} ${targets} ${results}
                    RESULT_VARIABLE status OUTPUT_VARIABLE text ERROR_VARIABLE errors)
    set(${out_status} "${status}" PARENT_SCOPE)
    set(${out_text} "${text}${errors}" PARENT_SCOPE)
endfunction()

# Met, not met, missing, from fewer runs and measured elsewhere each shown as such; exit 1 since
# not all are met.
report(${DATA}/targets.json ${DATA}/results status text)
file(READ ${DATA}/expected-report.md expected)
if(NOT text STREQUAL expected)
    message(FATAL_ERROR "bench_report's table differs from expected-report.md:\n${text}")
endif()
if(NOT status EQUAL 1)
    message(FATAL_ERROR "bench_report exited ${status} with figures not met or missing")
endif()

# A figure whose program failed in one run is judged on the runs it has, and says so.
report(${DATA}/targets-met.json ${DATA}/results status text)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "bench_report exited ${status} with every figure met:\n${text}")
endif()
if(NOT text MATCHES "; 2 of 3 runs, run 2: partial\\.2\\.json holds no JSON \\|"
   OR NOT text MATCHES "\n2 of 2 figures met.*; 1 from fewer than 3 runs\\.\n")
    message(FATAL_ERROR "bench_report does not say a figure lacks a run:\n${text}")
endif()

# The project's own targets: with no results every figure is missing, none met or failed.
report(${TARGETS} ${DATA}/no-such-results status text)
if(NOT status EQUAL 1 OR NOT text MATCHES "\n0 of ([0-9]+) figures met, 0 not met, ([0-9]+) missing"
   OR NOT CMAKE_MATCH_1 STREQUAL CMAKE_MATCH_2 OR CMAKE_MATCH_1 LESS 10)
    message(FATAL_ERROR "bench/targets.json does not read as a list of targets:\n${text}")
endif()
if(NOT text MATCHES "^Machine: not recorded \\(no machine\\.json in the results folder\\)\\.\n")
    message(FATAL_ERROR "bench_report does not say the machine is unknown:\n${text}")
endif()
