# A warped map's depth distribution, judged by the ground truth: one LiSPSM map
# on the street with the sun behind the camera. With hyperbolic z the slope-scale offset
# (bias.mode=slope, set here) in the warped depth swallows the car and wall shadows (false light
# ~3.9% at 640x360); the default `bias.distribution=auto` stores linear depth for the warps and
# must keep them. Both are run, so the test fails if the measurement stops seeing the difference.
# -D SHADOWLAB=<binary> -D WORK=<folder>
execute_process(COMMAND ${SHADOWLAB} generate street -o ${WORK}/street.glb RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "generate street failed (${rc})")
endif()
function(false_light distribution out)
  execute_process(COMMAND ${SHADOWLAB} render ${WORK}/street.glb --camera 0 --method lispsm --measure --truth
                          --set bias.distribution=${distribution} --set bias.mode=slope --set filter.filter=pcf2x2 --width 320 --height 180
                          --out ${WORK}/street-${distribution}.png
                  OUTPUT_VARIABLE text RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "render (${distribution}) failed (${rc}):\n${text}")
  endif()
  # lispsm row: ... undersampled% ... E_total% false-shadow% false-light% E_edge
  string(REGEX MATCH "\nlispsm [^\n]*" row "${text}")
  string(REGEX MATCHALL "[0-9.]+%" shares "${row}")
  list(LENGTH shares n)
  if(NOT n EQUAL 4)
    message(FATAL_ERROR "no lispsm row with the truth columns (${distribution}):\n${text}")
  endif()
  list(GET shares 3 light)
  string(REPLACE "%" "" light "${light}")
  message(STATUS "${distribution}: ${row}")
  set(${out} ${light} PARENT_SCOPE)
endfunction()
false_light(auto autoLight)
false_light(hyperbolic hyperbolicLight)
if(NOT autoLight LESS 1.0)
  message(FATAL_ERROR "auto (linear for LiSPSM): false light ${autoLight}% (want < 1%)")
endif()
if(NOT hyperbolicLight GREATER 2.0)
  message(FATAL_ERROR "hyperbolic: false light ${hyperbolicLight}%: the view no longer shows the loss this test guards")
endif()
