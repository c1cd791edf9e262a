# Warnings for every lifthull target: clean under gcc 12 and clang 14.
add_compile_options(
  "$<$<COMPILE_LANG_AND_ID:C,GNU,Clang>:-Wall;-Wextra;-Wshadow;-Wstrict-prototypes;-Wmissing-prototypes>"
  "$<$<COMPILE_LANG_AND_ID:CXX,GNU,Clang>:-Wall;-Wextra;-Wshadow>")
if(LH_WERROR)
  add_compile_options("$<$<COMPILE_LANG_AND_ID:C,GNU,Clang>:-Werror>")
endif()
