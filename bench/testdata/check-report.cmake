# CTest script for bench_report: the table's format, its verdicts and exit status on fixtures,
# and that bench/targets.json reads. Run as cmake -DREPORT=<bench_report> -DDATA=<this folder>
# -DTARGETS=<bench/targets.json> -P check-report.cmake.
function(report targets results out_status out_text)
    execute_process(COMMAND ${REPORT} ${targets} ${results}
                    RESULT_VARIABLE status OUTPUT_VARIABLE text ERROR_VARIABLE errors)
    set(${out_status} "${status}" PARENT_SCOPE)
    set(${out_text} "${text}${errors}" PARENT_SCOPE)
endfunction()

# Met, not met, missing and measured elsewhere each shown as such; exit 1 since not all are met.
report(${DATA}/targets.json ${DATA}/results status text)
file(READ ${DATA}/expected-report.md expected)
if(NOT text STREQUAL expected)
    message(FATAL_ERROR "bench_report's table differs from expected-report.md:\n${text}")
endif()
if(NOT status EQUAL 1)
    message(FATAL_ERROR "bench_report exited ${status} with figures not met or missing")
endif()

report(${DATA}/targets-met.json ${DATA}/results status text)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "bench_report exited ${status} with every figure met:\n${text}")
endif()

# The project's own targets: with no results every figure is missing, none met or failed.
report(${TARGETS} ${DATA}/no-such-results status text)
if(NOT status EQUAL 1 OR NOT text MATCHES "\n0 of ([0-9]+) figures met, 0 not met, ([0-9]+) missing"
   OR NOT CMAKE_MATCH_1 STREQUAL CMAKE_MATCH_2 OR CMAKE_MATCH_1 LESS 10)
    message(FATAL_ERROR "bench/targets.json does not read as a list of targets:\n${text}")
endif()
