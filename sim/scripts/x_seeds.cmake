# Runs the rpu_top testbench with several random initial-value seeds (--x-initial unique): each
# run must match the model on every result, so every seed gives identical results.
foreach(s 1 7 1234 99991)
  execute_process(COMMAND ${TB} frame --size 16 --x-seed ${s} RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  message(STATUS "x-seed ${s}: ${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "x-seed ${s} failed")
  endif()
endforeach()
