// The C++ consumer: the same API from C++ (the header is extern "C" and includes no GL header),
// linked through find_package(sss CONFIG). It checks the version macros and the GL-free kernel API,
// which an engine can use to build its own shader variant.
#include <sss/sss.h>

#include <array>
#include <cmath>
#include <cstdio>

int main() {
  sss_settings settings;
  sss_default_settings(&settings);
  std::array<float, SSS_MAX_SAMPLES * 4> taps{};
  if (sss_kernel_separable(settings.samples, settings.strength, settings.falloff, taps.data()) != SSS_OK) {
    std::fprintf(stderr, "%s\n", sss_last_error(nullptr));
    return 1;
  }
  double sum = 0.0;
  for (int i = 0; i < settings.samples; ++i) sum += taps[static_cast<std::size_t>(i) * 4];
  std::printf("sss %d.%d.%d from C++: %d taps, red weights sum to %.7f; %s for a NULL desc\n", SSS_VERSION_MAJOR,
              SSS_VERSION_MINOR, SSS_VERSION_PATCH, settings.samples, sum,
              sss_result_string(sss_create(nullptr, nullptr)));
  return std::fabs(sum - 1.0) < 1e-6 ? 0 : 1;
}
