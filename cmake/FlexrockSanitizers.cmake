# SPDX-License-Identifier: BSD-3-Clause
# applies FLEXROCK_SANITIZE to one target, so third-party code keeps its own flags
function(flexrock_apply_sanitizers target)
  if(FLEXROCK_SANITIZE)
    string(REPLACE ";" "," _list "${FLEXROCK_SANITIZE}")
    target_compile_options(${target} PRIVATE -fsanitize=${_list} -fno-sanitize-recover=all
                                             -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=${_list})
  endif()
endfunction()
