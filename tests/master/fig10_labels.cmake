# Fig. 10's counterpart (docs/contours.md) is labelled for what it measures: a 2 ms sample's whole
# work on the 8085 (timer, ramp, eqs. 4-6, pulse placement, OUT) beside a bare two-add DDA line loop,
# not the paper's interpolation-only rate against Koren's DDA and Middleditch's method. The figure is
# redrawn from the committed CSV (fig10_measure.py's columns by name) and must be the committed SVG.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${FIGURES} ${OUT} ${DOCS}/fig10.csv RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sampling_figures ${DOCS}/fig10.csv: status ${rc}")
endif()
file(READ ${OUT}/fig10.svg made)
file(READ ${DOCS}/fig10.svg committed)
if(NOT made STREQUAL committed)
  message(FATAL_ERROR "docs/contours/fig10.svg is not what sampling_figures draws from fig10.csv")
endif()
string(FIND "${made}" "<title>Fig. 10 on the ALP 85: a 2 ms sample&apos;s whole work / 6144 T-states</title>" at)
if(at EQUAL -1)
  message(FATAL_ERROR "fig10.svg: the title does not say what it measures")
endif()
# the legend is drawn as glyphs: its labels from the source that drew the committed figure
file(READ ${SOURCE} src)
foreach(need "sampling, line: whole sample (timer, ramp, eqs. 4-6, placement, OUT)"
             "bare DDA line loop (dda.asm: 2 adds + OUT; no timer, ramp, arcs), every 2 ms"
             "sampling, line: whole sample less the pulse placement")
  string(FIND "${src}" "\"${need}\"" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${SOURCE}: Fig. 10's legend lacks: ${need}")
  endif()
endforeach()
string(FIND "${made}" "occupation rate" at)
if(NOT at EQUAL -1)
  message(FATAL_ERROR "fig10.svg still calls the whole sample's share the paper's occupation rate")
endif()
file(STRINGS ${DOCS}/fig10.csv header LIMIT_COUNT 1)
if(NOT header MATCHES "^feed,line_sample,line_sample_jobs,arc_sample,arc_sample_jobs,bare_dda_line,")
  message(FATAL_ERROR "fig10.csv: the columns are not named for what they measure: ${header}")
endif()
