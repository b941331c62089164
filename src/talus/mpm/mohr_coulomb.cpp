// Mohr-Coulomb return mapping in principal stresses (de Souza Neto, Peric &
// Owen 2008, box 8.5, perfect plasticity): return to the main plane; when the
// principal order breaks, to the edge where two planes meet; when that fails
// too, to the apex. Closed form at every stage, so f <= 0 holds to round-off.
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "talus/mpm/materials.hpp"

namespace talus::mpm {

namespace {

using Vec3 = Eigen::Vector3d;

struct Plane {
  Vec3 nf, ng;  // yield normal and flow direction in (s1, s2, s3)
};

// The plane through principal stresses (major, minor).
Plane plane(int major, int minor, double sin_phi, double sin_psi) {
  Plane p{Vec3::Zero(), Vec3::Zero()};
  p.nf[major] = 1.0 + sin_phi;
  p.nf[minor] = -(1.0 - sin_phi);
  p.ng[major] = 1.0 + sin_psi;
  p.ng[minor] = -(1.0 - sin_psi);
  return p;
}

bool ordered(const Vec3& s, double tol) { return s[0] >= s[1] - tol && s[1] >= s[2] - tol; }

}  // namespace

double MohrCoulomb::yield(const Mat3& stress, double cohesion) const {
  Eigen::SelfAdjointEigenSolver<Mat3> eig(stress, Eigen::EigenvaluesOnly);
  const double s1 = eig.eigenvalues()[2], s3 = eig.eigenvalues()[0];
  return (s1 - s3) + (s1 + s3) * std::sin(phi) - 2.0 * cohesion * std::cos(phi);
}

Mat3 MohrCoulomb::update_returning(MaterialState& s, const Mat3& l, double dt,
                                   double dv_over_v0) const {
  const Mat3 strain = sym(l) * dt;
  const Mat3 trial = rotate_stress(s.stress, skew(l) * dt) + 2.0 * k.shear * deviator(strain) +
                     k.bulk * strain.trace() * Mat3::Identity();
  Eigen::SelfAdjointEigenSolver<Mat3> eig(trial);
  // Principal stresses s1 >= s2 >= s3 and their directions.
  const Vec3 st(eig.eigenvalues()[2], eig.eigenvalues()[1], eig.eigenvalues()[0]);
  Mat3 dirs;
  dirs << eig.eigenvectors().col(2), eig.eigenvectors().col(1), eig.eigenvectors().col(0);

  const double sp = std::sin(phi), cp = std::cos(phi), sg = std::sin(psi);
  auto f_of = [&](const Plane& pl, const Vec3& sig, double c) {
    return pl.nf.dot(sig) - 2.0 * c * cp;
  };
  const Plane main = plane(0, 2, sp, sg);
  s.yielding = f_of(main, st, s.cohesion) > 0.0;
  if (!s.yielding) {
    s.stress = trial;
    return Mat3::Zero();
  }
  lose_cohesion(s, c0, critical_volume_strain, dv_over_v0);
  const double c = s.cohesion;
  const double lambda = k.bulk - 2.0 / 3.0 * k.shear;
  Mat3 elastic = lambda * Mat3::Ones() + 2.0 * k.shear * Mat3::Identity();
  const double tol = 1e-12 * (st.cwiseAbs().maxCoeff() + c);

  Vec3 sig = st;
  bool done = false;
  const double fa = f_of(main, st, c);
  if (fa > 0.0) {
    const double dga = fa / main.nf.dot(elastic * main.ng);
    sig = st - dga * elastic * main.ng;
    done = ordered(sig, tol);
    if (!done) {
      // The edge where s1 = s2 (the returned s2 passed s1) or s2 = s3.
      const bool upper = sig[1] > sig[0];
      const Plane other = upper ? plane(1, 2, sp, sg) : plane(0, 1, sp, sg);
      Eigen::Matrix2d a;
      a << main.nf.dot(elastic * main.ng), main.nf.dot(elastic * other.ng),
          other.nf.dot(elastic * main.ng), other.nf.dot(elastic * other.ng);
      const Eigen::Vector2d dg = a.inverse() * Eigen::Vector2d(fa, f_of(other, st, c));
      sig = st - dg[0] * elastic * main.ng - dg[1] * elastic * other.ng;
      done = dg[0] >= 0.0 && dg[1] >= 0.0 && ordered(sig, tol);
    }
  } else {
    done = true;  // cohesion unchanged and already inside: cannot happen, kept safe
  }
  if (!done) {
    // The apex p = c cot(phi); without friction there is none and the edge stands.
    if (sp > 0.0) sig.setConstant(c * cp / sp);
  }
  s.stress = dirs * sig.asDiagonal() * dirs.transpose();
  const Vec3 dep = elastic.inverse() * (st - sig);
  const Mat3 plastic = dirs * dep.asDiagonal() * dirs.transpose();
  const Mat3 e = deviator(plastic);
  s.plastic_strain += std::sqrt(2.0 / 3.0 * (e.array() * e.array()).sum());
  return plastic;
}

double MohrCoulomb::wave_speed() const { return std::sqrt(k.p_modulus() / density); }

}  // namespace talus::mpm
