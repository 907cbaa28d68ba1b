# The caster model on a closed room of single-sided inward-facing walls (generate interior) and on
# the same room inside a sky box (--skybox), by the ground truth, default settings, every method:
#  - every camera's E_total <= 2% (before the caster model the map cast front faces only and the
#    truth every face: 82-88% false light here);
#  - the sky box is detected as a backdrop, named in a note, and changes no E_total by more than
#    0.3 points (different map fits sample the slats differently at this size).
# -D SHADOWLAB=<binary> -D WORK=<folder>
foreach(variant interior interior-skybox)
  set(flags)
  if(variant STREQUAL "interior-skybox")
    set(flags --skybox)
  endif()
  execute_process(COMMAND ${SHADOWLAB} generate interior ${flags} -o ${WORK}/${variant}.glb RESULT_VARIABLE rc OUTPUT_QUIET)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "generate interior ${flags} failed (${rc})")
  endif()
endforeach()

# E_total of every method row, in order, into `out`; the render's stderr into `notes`.
function(e_totals scene camera out notes)
  execute_process(COMMAND ${SHADOWLAB} render ${WORK}/${scene}.glb --camera ${camera} --method all --measure --truth
                          --width 320 --height 180 --out ${WORK}/${scene}-${camera}.png ${ARGN}
                  OUTPUT_VARIABLE text ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "render ${scene} camera ${camera} failed (${rc}):\n${text}\n${err}")
  endif()
  string(REGEX MATCHALL "\n(ssm|psm|lispsm|csm-ssm|csm-stable|csm-lispsm) [^\n]*" rows "${text}")
  set(totals)
  foreach(row ${rows})
    string(REGEX MATCHALL "[0-9.]+%" shares "${row}")
    list(LENGTH shares n)
    if(NOT n EQUAL 4)
      message(FATAL_ERROR "a method row without the truth columns (${scene} ${camera}):\n${text}")
    endif()
    list(GET shares 1 total)
    string(REPLACE "%" "" total "${total}")
    list(APPEND totals ${total})
  endforeach()
  list(LENGTH totals n)
  if(NOT n EQUAL 6)
    message(FATAL_ERROR "expected 6 method rows (${scene} ${camera}), got ${n}:\n${text}")
  endif()
  message(STATUS "${scene} camera ${camera} ${ARGN}: E_total ${totals}")
  set(${out} ${totals} PARENT_SCOPE)
  set(${notes} "${err}" PARENT_SCOPE)
endfunction()

function(hundredths value out)
  string(REGEX REPLACE "^([0-9]+)\\.([0-9])([0-9]).*$" "\\1\\2\\3" digits "${value}00")
  string(REGEX REPLACE "^0+([0-9])" "\\1" digits "${digits}")
  set(${out} ${digits} PARENT_SCOPE)
endfunction()

foreach(camera 0 1 2)
  e_totals(interior ${camera} room roomNotes)
  e_totals(interior-skybox ${camera} sky skyNotes)
  if(NOT skyNotes MATCHES "node 'SkyBox' [^\n]*backdrop[^\n]*casters.include")
    message(FATAL_ERROR "no note naming the excluded sky box (camera ${camera}):\n${skyNotes}")
  endif()
  foreach(i RANGE 5)
    list(GET room ${i} r)
    list(GET sky ${i} s)
    if(r GREATER 2.0)
      message(FATAL_ERROR "interior camera ${camera}, method row ${i}: E_total ${r}% (want <= 2%)")
    endif()
    # CMake's math is integer: the difference in hundredths of a point (the table prints two decimals).
    hundredths(${r} rHundredths)
    hundredths(${s} sHundredths)
    math(EXPR diff "${sHundredths} - ${rHundredths}")
    if(diff GREATER 30 OR diff LESS -30)
      message(FATAL_ERROR "camera ${camera}, method row ${i}: E_total ${r}% without the sky box, ${s}% with it")
    endif()
  endforeach()
endforeach()
