# docs/contours.md cites Watanabe and Iwai's paper by its own title and volume, as its first page
# and the volume's contents print them (the OCR text ../shared/seeds/000_49beea4987989b4c.txt):
# "An Application of a Mini-Computer to a Computer Numerical Control System of a Machine Tool",
# pp. 1-6 of the IEEE 1981 proceedings, catalog no. 81CH1714-5. "A method to decrease computing
# time of interpolation algorithm" is the first sentence of its abstract, not its title.
file(READ ${DOC} text)
string(REGEX REPLACE "[ \n]+" " " text "${text}")
foreach(need "T. Watanabe and S. Iwai, \"An Application of a Mini-Computer to a Computer Numerical Control System of a Machine Tool\""
             "IEEE 1981 IECE Proceedings" "81CH1714-5" "pp. 1–6")
  string(FIND "${text}" "${need}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${DOC}: the citation lacks: ${need}")
  endif()
endforeach()
string(FIND "${text}" "IECI '81, \"A method to decrease" at)
if(NOT at EQUAL -1)
  message(FATAL_ERROR "${DOC}: cites the abstract's first sentence as the paper's title")
endif()
