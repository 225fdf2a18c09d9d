// A radially symmetric diffusion profile R_c(r), per colour channel, as the pre-integrated LUT
// generators (and later the other material profiles) take it. Math layer: no GL.
//
// Why an interface: the LUTs only ever need R_c at a distance, a distance beyond which R is
// negligible (to bound the integrals) and a stable identity (to key the cache). Any profile that can
// answer those three plugs into the generators; the d'Eon–Luebke skin sum of Gaussians is the default.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "skin_profile.hpp"

namespace sss::math {

class RadialProfile {
 public:
  virtual ~RadialProfile() = default;
  // R_c(r) for the three channels, r in mm (>= 0). Any positive scale: the LUTs normalise.
  virtual std::array<double, 3> evaluate(double r_mm) const = 0;
  // Radius (mm) beyond which every channel is negligible (< 1e-9 of its mass lies further out).
  virtual double support_mm() const = 0;
  // Text that changes whenever the values change (name and parameters): the cache key's part.
  virtual std::string identity() const = 0;
  // The terms when the profile is a sum of 2D-normalised Gaussians (the GPU generator evaluates
  // those in closed form), else nullptr (generated on the CPU).
  virtual const std::vector<GaussianTerm>* gaussian_terms() const { return nullptr; }
};

// A sum of 2D-normalised Gaussians (skin_profile.hpp's GaussianTerm).
class SumOfGaussiansProfile final : public RadialProfile {
 public:
  SumOfGaussiansProfile(std::string name, std::vector<GaussianTerm> terms);
  std::array<double, 3> evaluate(double r_mm) const override;
  double support_mm() const override { return support_mm_; }
  std::string identity() const override { return identity_; }
  const std::vector<GaussianTerm>* gaussian_terms() const override { return &terms_; }

 private:
  std::vector<GaussianTerm> terms_;
  double support_mm_ = 0.0;
  std::string identity_;
};

// d'Eon and Luebke's six-Gaussian skin (skin_profile.hpp), the default of the C API.
const RadialProfile& deon_skin_profile();

}  // namespace sss::math
