# LH_SANITIZE=ON: AddressSanitizer + UndefinedBehaviorSanitizer on every target,
# with UB made fatal so that a sanitizer finding fails the test that hit it.
if(LH_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
