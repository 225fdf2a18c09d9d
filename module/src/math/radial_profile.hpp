// Radially symmetric diffuse reflectance profiles R_c(r) (per RGB channel, mm⁻²): the one
// definition every kernel family is built from. Math layer: no GL.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "materials.hpp"
#include "skin_profile.hpp"

namespace sss::math {

using Rgb = std::array<double, 3>;

class RadialProfile {
 public:
  virtual ~RadialProfile() = default;
  // R_c(r) per channel, in mm⁻² (reflected flux per unit area per unit incident flux).
  virtual Rgb evaluate(double r_mm) const = 0;
  // ∫∫ R_c dA over the plane: the total diffuse reflectance per channel.
  virtual Rgb integral() const = 0;
  // A radius (mm) outside which every channel holds less than 1e-4 of its integral: the end of
  // the numeric integrations and the default reach of kernels built from the profile.
  virtual double extent_mm() const = 0;
};

// A sum of 2D-normalised Gaussians (d'Eon–Luebke form). The first `count` terms of `terms`,
// each channel's weights rescaled to sum to 1 (count = 6 with skin_gaussians(): the full profile).
class GaussianSumProfile final : public RadialProfile {
 public:
  explicit GaussianSumProfile(std::vector<GaussianTerm> terms);
  static GaussianSumProfile skin(int count);  // the first `count` (1..6) of skin_gaussians()
  Rgb evaluate(double r_mm) const override;
  Rgb integral() const override;
  double extent_mm() const override;
  const std::vector<GaussianTerm>& terms() const { return terms_; }

 private:
  std::vector<GaussianTerm> terms_;
};

// The classical dipole (Jensen, Marschner, Levoy, Hanrahan 2001, eq. 4-5) for a semi-infinite
// medium with isotropic scattering (σs' = σs because g = 0 in the §G table).
class DipoleProfile final : public RadialProfile {
 public:
  explicit DipoleProfile(const MaterialCoefficients& m);
  Rgb evaluate(double r_mm) const override;
  Rgb integral() const override;  // closed form: α'/2 · (exp(-σtr zr) + exp(-σtr zv))
  double extent_mm() const override;
  // ∫∫ over the disk of radius r_mm, closed form per channel.
  Rgb encircled(double r_mm) const;

 private:
  struct Channel {
    double albedo, sigma_tr, z_r, z_v;
  };
  std::array<Channel, 3> ch_{};
};

// A user-given table: radii (strictly increasing, ≥ 0, mm) and R_c at each, linearly interpolated,
// held constant from 0 to the first radius, zero beyond the last.
class TabulatedProfile final : public RadialProfile {
 public:
  TabulatedProfile(std::vector<double> radii_mm, std::vector<Rgb> values);
  Rgb evaluate(double r_mm) const override;
  Rgb integral() const override;  // exact for the piecewise-linear profile
  double extent_mm() const override { return radii_.empty() ? 0.0 : radii_.back(); }

 private:
  std::vector<double> radii_;
  std::vector<Rgb> values_;
};

// Fresnel diffuse reflectance F_dr (Egan & Hilgeman's fit, as Jensen et al. 2001 use it).
double fresnel_diffuse_reflectance(double eta);

// ∫∫ over the disk of radius r_mm by numeric quadrature of 2πr·R(r): for any profile.
Rgb encircled_numeric(const RadialProfile& p, double r_mm);

// The smallest radius inside which every channel holds at least `fraction` of its integral.
double radius_enclosing(const RadialProfile& p, double fraction);

}  // namespace sss::math
