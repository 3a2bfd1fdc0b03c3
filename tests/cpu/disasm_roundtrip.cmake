# Disassembles an image to source (alp85 disasm --source), assembles that with asm85 and checks
# that the bytes are the same: the listings of the original and of the result (addresses and
# bytes of every line, no symbols) must be identical.
#   cmake -DALP85=alp85 -DASM85=asm85 -DIMAGE="file;--org;0" -DCPU=8080|8085 -DWORK=dir -P ...
file(MAKE_DIRECTORY ${WORK})
set(asm_cpu ${CPU})
if(CPU STREQUAL "8085")
  set(asm_cpu 8085u)
endif()
execute_process(COMMAND ${ALP85} disasm ${IMAGE} --cpu ${CPU} --source -o ${WORK}/rt.asm
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "alp85 disasm --source failed (${rc}): ${err}")
endif()
execute_process(COMMAND ${ASM85} --cpu ${asm_cpu} -q ${WORK}/rt.asm -o ${WORK}/rt.hex
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "asm85 rejects the disassembly (${rc}): ${out}${err}")
endif()
execute_process(COMMAND ${ALP85} disasm ${IMAGE} --cpu ${CPU} --no-symbols OUTPUT_VARIABLE before RESULT_VARIABLE rc1)
execute_process(COMMAND ${ALP85} disasm ${WORK}/rt.hex --cpu ${CPU} --no-symbols OUTPUT_VARIABLE after RESULT_VARIABLE rc2)
if(NOT rc1 EQUAL 0 OR NOT rc2 EQUAL 0 OR NOT before STREQUAL after OR before STREQUAL "")
  file(WRITE ${WORK}/before.lst "${before}")
  file(WRITE ${WORK}/after.lst "${after}")
  message(FATAL_ERROR "the re-assembled bytes differ: compare ${WORK}/before.lst and ${WORK}/after.lst")
endif()
