// tinygltf's and stb_image's implementations for the WebAssembly build. Natively Debian's
// libtinygltf holds them (integration/gltf_mesh links it); for emcc only the headers exist, so the
// page compiles them here, from the same Debian headers, which decode the head's JPEGs bit for bit
// as the native library does.
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <tiny_gltf.h>
