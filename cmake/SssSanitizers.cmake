# With SSS_SANITIZE=ON every target in the tree is built and linked with ASan and UBSan; UBSan
# findings abort (no recovery) so that ctest sees them as failures.
if(SSS_SANITIZE)
  if(MSVC)
    message(FATAL_ERROR "SSS_SANITIZE is for GCC and Clang")
  endif()
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
