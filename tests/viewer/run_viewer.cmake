# Runs the viewer for a few frames under Xvfb on the default scene and checks it exited with 0 and
# wrote a non-trivial screenshot.
file(REMOVE ${OUT})
execute_process(
  COMMAND ${XVFB_RUN} -n ${FIRST_DISPLAY} -a -s "-screen 0 1280x720x24" ${SHADOWLAB} --frames 5 --width 640 --height 360 --screenshot ${OUT}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "viewer exited with ${rc}")
endif()
if(NOT EXISTS ${OUT})
  message(FATAL_ERROR "viewer did not write the screenshot ${OUT}")
endif()
file(SIZE ${OUT} size)
if(size LESS 2000)
  message(FATAL_ERROR "screenshot ${OUT} is only ${size} bytes")
endif()
