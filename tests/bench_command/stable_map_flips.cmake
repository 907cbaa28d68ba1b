# Shimmering of the map alone (stable shadow maps): the temporal instrument draws the
# first frame again from its own camera with the shadows set up for the moved camera, so every
# pixel shows the same surface point and only the map differs. On the forest's side-sun view the
# stable cascades must not change one pixel's state under the 1 px step, the 0.1 deg turn and the
# 2 cm walk (measured 0 of 37,893 receivers at 320x180), while the focused map changes ~0.5% of them:
# run both, so the test fails if the measure stops seeing shimmering where there is some.
# -D SHADOWLAB=<binary> -D SCENE=<forest.glb> -D WORK=<folder>
function(map_flips method out)
  execute_process(COMMAND ${SHADOWLAB} render ${SCENE} --camera 0 --method ${method} --measure --truth --temporal
                          --width 320 --height 180 --out ${WORK}/flips-${method}.png
                  OUTPUT_VARIABLE text RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "render (${method}) failed (${rc}):\n${text}")
  endif()
  string(REGEX MATCHALL "the map alone [0-9.]+% of [0-9]+" steps "${text}")
  list(LENGTH steps n)
  if(NOT n EQUAL 3)
    message(FATAL_ERROR "${method}: no three temporal steps with the map's own share:\n${text}")
  endif()
  set(shares)
  foreach(step IN LISTS steps)
    string(REGEX REPLACE "the map alone ([0-9.]+)% of ([0-9]+)" "\\1" share "${step}")
    string(REGEX REPLACE "the map alone ([0-9.]+)% of ([0-9]+)" "\\2" points "${step}")
    if(points LESS 10000)
      message(FATAL_ERROR "${method}: only ${points} receivers compared:\n${text}")
    endif()
    list(APPEND shares ${share})
  endforeach()
  message(STATUS "${method}: the map alone ${shares} %")
  set(${out} ${shares} PARENT_SCOPE)
endfunction()
map_flips(csm-stable stable)
map_flips(ssm focused)
foreach(share IN LISTS stable)
  if(NOT share EQUAL 0)
    message(FATAL_ERROR "stable cascades: the map alone changed ${share}% of the receivers (want 0)")
  endif()
endforeach()
list(GET focused 0 step)
if(NOT step GREATER 0.1)
  message(FATAL_ERROR "focused map: the 1 px step changed ${step}% (want > 0.1%): the view no longer shimmers")
endif()
