# With SSS_SANITIZE=ON every target in the tree is built and linked with ASan and UBSan; UBSan
# findings abort (no recovery) so that ctest sees them as failures.
#
# At -O1 with line tables only (-g1): the level AddressSanitizer's documentation suggests, and its
# reports name file and line all the same. On a 2-core machine like CI's the build of this tree at the
# build type's -O2 -g took 8.3 minutes against the release build's 3.6 (instrumented template-heavy
# test code: GoogleTest, Eigen, nlohmann-json); these flags compile each file 2.0-2.3 times
# faster. They come after the build type's flags, and GCC and Clang take the last -O and -g given.
if(SSS_SANITIZE)
  if(MSVC)
    message(FATAL_ERROR "SSS_SANITIZE is for GCC and Clang")
  endif()
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -O1 -g1)
  add_link_options(-fsanitize=address,undefined)
endif()
