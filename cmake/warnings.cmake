# Warnings and build flavours shared by every lbdem target (through the interface target lbdem_flags).
add_library(lbdem_flags INTERFACE)
target_compile_options(lbdem_flags INTERFACE -Wall -Wextra -Wpedantic)
# GCC 12 reports a false -Wrestrict inside std::string concatenation (GCC bug 105651).
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  target_compile_options(lbdem_flags INTERFACE -Wno-restrict)
endif()
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
  target_compile_definitions(lbdem_flags INTERFACE LBDEM_NO_FLATTEN)
  # GCC documents that -fsanitize makes -Wmaybe-uninitialized report false positives (seen in
  # libstdc++'s <regex> through Catch2); the Release build keeps the warning.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(lbdem_flags INTERFACE -Wno-maybe-uninitialized)
  endif()
endif()
