// Christensen and Burley's normalized diffusion ("Approximate Reflectance Profiles for Efficient
// Subsurface Scattering", Pixar technical memo 2015): per RGB channel,
//
//   R(r) = A · (e^{-r/d} + e^{-r/(3d)}) / (8π d r)      (mm⁻²)
//
// A the surface albedo (the total diffuse reflectance, ∫∫ R dA = A), d the shape in mm. The artist
// gives the diffuse mean free path ℓ_d (mm); d = ℓ_d / s with the memo's fit for ℓ_d (diffuse
// surface transmission, its eq. 8) s(A) = 3.5 + 100 (A − 0.33)⁴. The memo's other fits,
// 1.85 − A + 7|A − 0.8|³ (searchlight) and 1.9 − A + 3.5 (A − 0.8)² (diffuse transmission), take
// the mean free path ℓ = 1/σt instead, which an artist rarely knows: not used here.
//
// Closed forms: the energy within radius r, A (1 − e^{-r/d}/4 − 3e^{-r/(3d)}/4), and outside it,
// A (e^{-r/d} + 3e^{-r/(3d)})/4. R is infinite at r = 0 (the 1/r): integrals over cells go
// through those closed forms (radial_integrals.hpp), never through R at the centre.
// Math layer: no GL.
#pragma once

#include <string>

#include "materials.hpp"
#include "radial_profile.hpp"

namespace sss::math {

struct BurleyParameters {
  Rgb albedo{};   // A per channel, (0, 1]
  Rgb dmfp_mm{};  // ℓ_d per channel, mm, > 0
};

// The memo's eq. 8: ℓ_d / d as a function of the surface albedo A.
double burley_dmfp_scaling(double albedo);

// The Burley parameters of a measured material (Jensen et al. 2001's σa, σs', η): A = the dipole's
// total diffuse reflectance R_d (DipoleProfile::integral), ℓ_d = 1/σtr with σtr = √(3σa(σa + σs')),
// the memo's definition of the diffuse mean free path.
BurleyParameters burley_from_material(const MaterialCoefficients& m);

// The default parameters of the public API: Jensen et al.'s skin1 through burley_from_material.
BurleyParameters burley_default_parameters();

class BurleyProfile final : public RadialProfile {
 public:
  explicit BurleyProfile(const BurleyParameters& p);
  Rgb evaluate(double r_mm) const override;  // +infinity at r = 0
  Rgb integral() const override { return albedo_; }
  double extent_mm() const override;
  double support_mm(double tail_fraction) const override;  // bisection on the closed-form outside()
  std::string identity() const override;
  bool singular_at_centre() const override { return true; }
  Rgb outside(double r_mm) const override;   // closed form
  Rgb encircled(double r_mm) const override;  // closed form
  const Rgb& shape_mm() const { return d_; }  // d per channel

 private:
  Rgb albedo_{};
  Rgb d_{};
};

}  // namespace sss::math
