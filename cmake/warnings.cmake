# Warnings and build flavours shared by every lbdem target (through the interface target lbdem_flags).
add_library(lbdem_flags INTERFACE)
target_compile_options(lbdem_flags INTERFACE -Wall -Wextra -Wpedantic)
if(LBDEM_WERROR)
  target_compile_options(lbdem_flags INTERFACE -Werror)
endif()
if(LBDEM_NATIVE AND NOT LBDEM_SANITIZE)
  target_compile_options(lbdem_flags INTERFACE $<$<CONFIG:Release>:-march=native>)
endif()
if(LBDEM_SANITIZE)
  target_compile_options(lbdem_flags INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
                                               -fno-sanitize-recover=undefined)
  target_link_options(lbdem_flags INTERFACE -fsanitize=address,undefined)
endif()
