// Radially symmetric diffuse reflectance profiles R_c(r) (per RGB channel, mm⁻²): the one
// definition every kernel family is built from. Math layer: no GL.
#pragma once

#include <array>
#include <memory>
#include <string>
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

  // What the pre-integrated LUT generators (preintegrated_lut.hpp) need beyond the above; defaults
  // work for any profile, subclasses answer exactly or faster.
  //
  // A radius (mm) outside which every channel holds less than `tail_fraction` of its integral. The
  // LUTs bound their integrals with 1e-9, far below extent_mm()'s 1e-4, which would cost them their
  // 1e-3 accuracy. Default: doubling from extent_mm(), then bisection on encircled_numeric().
  virtual double support_mm(double tail_fraction) const;
  // Text that changes whenever the values change (kind and parameters): the LUT cache key's part.
  // Default: R at fixed radii and the integral, printed exactly.
  virtual std::string identity() const;
  // The terms when the profile is a sum of 2D-normalised Gaussians (the GPU LUT generator and the
  // normal blur evaluate those in closed form), else nullptr.
  virtual const std::vector<GaussianTerm>* gaussian_terms() const { return nullptr; }

  // What integrals over cells (radial_integrals.hpp) need from profiles whose R is infinite at the
  // centre (Burley's 1/r), where sampling R fails: the energy inside and outside a radius, per
  // channel. Defaults: encircled_numeric(), and integral() minus it; subclasses answer in closed
  // form, outside() without the cancellation of the difference in the far tail.
  virtual bool singular_at_centre() const { return false; }
  virtual Rgb encircled(double r_mm) const;
  virtual Rgb outside(double r_mm) const;
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
  double support_mm(double tail_fraction) const override;  // closed form
  std::string identity() const override;
  const std::vector<GaussianTerm>* gaussian_terms() const override { return &terms_; }
  Rgb outside(double r_mm) const override;  // closed form: Σ w · exp(-r²/2v)
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
  double support_mm(double tail_fraction) const override;  // bisection on the closed-form encircled()
  std::string identity() const override;
  // ∫∫ over the disk of radius r_mm, closed form per channel.
  Rgb encircled(double r_mm) const override;

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
  double support_mm(double /*tail_fraction*/) const override { return extent_mm(); }  // zero beyond
  std::string identity() const override;

 private:
  std::vector<double> radii_;
  std::vector<Rgb> values_;
};

// d'Eon and Luebke's six-Gaussian skin (GaussianSumProfile::skin(6)), built once: the default
// profile of the pre-integrated LUTs.
const GaussianSumProfile& deon_skin_profile();

// Fresnel diffuse reflectance F_dr (Egan & Hilgeman's fit, as Jensen et al. 2001 use it).
double fresnel_diffuse_reflectance(double eta);

// ∫∫ over the disk of radius r_mm by numeric quadrature of 2πr·R(r): for any profile whose r·R(r)
// is bounded at the centre (R itself may not be: the r = 0 sample is never taken).
Rgb encircled_numeric(const RadialProfile& p, double r_mm);

// The smallest radius inside which every channel holds at least `fraction` of its integral.
double radius_enclosing(const RadialProfile& p, double fraction);

}  // namespace sss::math
