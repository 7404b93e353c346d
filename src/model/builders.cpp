// SPDX-License-Identifier: BSD-3-Clause
// Builders of the paper's parameters (Moran & McLennan 1995, KINETICS) from engineering data:
// every parameter is its integral over the body, here sums over nodes or quadrature along a beam.
#include "flexrock/model/builders.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/model/assemblies.hpp"

namespace flexrock {

namespace {

constexpr int kMaxBuilderModes = 20;       // modes a closed-form builder may generate
constexpr double kTipTolerance = 1e-9;     // [m] a node this close to a tipping point is on it
constexpr double kPinnedTolerance = 1e-6;  // |phi| at a tipping point relative to max |phi|
constexpr double kOrthogonality = 1e-6;    // |m_ij| relative to sqrt(m_ii m_jj), i != j
// shapes printed to 4 significant digits are orthogonal only to about 1e-4 relative (rounding of
// each printed value by up to 5e-4 of it, summed over the nodes): up to this figure they are
// re-orthogonalised, above it the shapes are not the modes of one mass matrix
constexpr double kPrintedOrthogonality = 1e-2;
constexpr double kSymmetryTolerance = 1e-8;  // given stiffness, relative to its largest entry

std::string num(double v) { return format_number(v, 6); }

std::string idx(Eigen::Index i) { return std::to_string(i + 1); }

void require_positive(const char* where, const char* name, double v, const char* unit) {
  FLEXROCK_THROW_UNLESS(std::isfinite(v) && v > 0.0, std::string(where) + ": " + name + " " + unit +
                                                         " must be > 0 and finite, got " + num(v));
}

void require_non_negative(const char* where, const char* name, double v, const char* unit) {
  FLEXROCK_THROW_UNLESS(
      std::isfinite(v) && v >= 0.0,
      std::string(where) + ": " + name + " " + unit + " must be >= 0 and finite, got " + num(v));
}

void require_damping_ratio(const char* where, double zeta) {
  FLEXROCK_THROW_UNLESS(std::isfinite(zeta) && zeta >= 0.0 && zeta < 1.0,
                        std::string(where) + ": damping_ratio must be in [0, 1), got " + num(zeta));
}

Damping modal_damping(int n, double zeta) {
  Damping d;
  d.kind = DampingKind::kModal;
  d.modal_ratios = VectorX::Constant(n, zeta);
  return d;
}

// clamped-free Euler-Bernoulli mode in x = b y, X = b L; the hyperbolic part is written with
// e^(x - X) and e^(-x) so that no term exceeds O(1) for any mode (cosh - s sinh cancels otherwise)
struct CantileverMode {
  double X = 0.0;  // b L, a root of cos X cosh X = -1
  double s = 0.0;  // (cosh X + cos X)/(sinh X + sin X)
  double a = 0.0;  // (1 - s) e^X / 2, the coefficient of e^(x - X)
  double c = 0.0;  // (1 + s)/2, the coefficient of e^(-x)

  explicit CantileverMode(double root) : X(root) {
    const double e = std::exp(-X);
    const double den = 1.0 - e * e + 2.0 * std::sin(X) * e;  // 2 e^-X (sinh X + sin X)
    s = (1.0 + e * e + 2.0 * std::cos(X) * e) / den;
    a = (std::sin(X) - std::cos(X) - e) / den;
    c = 0.5 * (1.0 + s);
  }
  // cosh x - s sinh x
  double hyperbolic(double x) const { return a * std::exp(x - X) + c * std::exp(-x); }
  // cosh x - cos x - s (sinh x - sin x)
  double shape(double x) const { return hyperbolic(x) - std::cos(x) + s * std::sin(x); }
  // d^2/dx^2 of shape: cosh x + cos x - s (sinh x + sin x)
  double curvature(double x) const { return hyperbolic(x) + std::cos(x) - s * std::sin(x); }
};

// i-th root (1-based) of cos X cosh X = -1; it lies in ((i - 1) pi, i pi)
double cantilever_root(int i) {
  // cos X + 1/cosh X: same roots, no overflow
  auto f = [](double x) { return std::cos(x) + 1.0 / std::cosh(x); };
  const double lo = (i - 1) * std::numbers::pi, hi = i * std::numbers::pi;
  std::uintmax_t iters = 200;
  const auto r = boost::math::tools::toms748_solve(
      f, lo, hi, f(lo), f(hi), boost::math::tools::eps_tolerance<double>(53), iters);
  FLEXROCK_DEMAND(iters < 200);
  return 0.5 * (r.first + r.second);
}

// integral of f over [0, L] by composite 20-point Gauss-Legendre on `panels` equal panels
template <class F>
double integrate(F f, double L, int panels) {
  const double w = L / panels;
  double sum = 0.0;
  for (int p = 0; p < panels; ++p)
    sum += boost::math::quadrature::gauss<double, 20>::integrate(f, p * w, (p + 1) * w);
  return sum;
}

}  // namespace

BodyParameters rigid_block(double width, double height, double mass) {
  constexpr const char* kWhere = "rigid_block";
  require_positive(kWhere, "width", width, "[m]");
  require_positive(kWhere, "height", height, "[m]");
  require_positive(kWhere, "mass", mass, "[kg]");
  const double h = 0.5 * height;
  // I_zz = M (w^2 + H^2)/12 about the centre
  return BodyParameters::rigid(mass, h, 0.5 * width, 0.5 * width,
                               (width * width + height * height) / (12.0 * h * h));
}

BodyParameters taken_rigid(const BodyParameters& body) {
  BodyParameters p = BodyParameters::rigid(body.mass, body.height, body.b1, body.b2, body.zeta2);
  p.gravity = body.gravity;
  return p;
}

BodyParameters rigid_body(double mass, double inertia_cg, double height, double b1, double b2) {
  constexpr const char* kWhere = "rigid_body";
  require_positive(kWhere, "mass", mass, "[kg]");
  require_positive(kWhere, "inertia_cg", inertia_cg, "[kg m^2]");
  require_positive(kWhere, "height", height, "[m]");
  require_positive(kWhere, "b1", b1, "[m]");
  require_positive(kWhere, "b2", b2, "[m]");
  return BodyParameters::rigid(mass, height, b1, b2, inertia_cg / (mass * height * height));
}

BodyParameters from_lumped_model(const LumpedModel& model) {
  std::vector<std::string> notes;
  return from_lumped_model(model, notes);
}

BodyParameters from_lumped_model(const LumpedModel& model, std::vector<std::string>& notes) {
  constexpr const char* kWhere = "lumped model";
  const std::string where = kWhere;
  const auto& nodes = model.nodes;
  const Eigen::Index nn = static_cast<Eigen::Index>(nodes.size());
  FLEXROCK_THROW_UNLESS(nn > 0, where + ": nodes must not be empty");
  require_positive(kWhere, "gravity", model.gravity, "[m/s^2]");

  // nodes and the undeformed c.g.
  double M = 0.0, xm = 0.0, ym = 0.0;
  for (Eigen::Index k = 0; k < nn; ++k) {
    const LumpedNode& nd = nodes[static_cast<std::size_t>(k)];
    const std::string node = where + ": node " + idx(k);
    FLEXROCK_THROW_UNLESS(
        std::isfinite(nd.x) && std::isfinite(nd.y),
        node + " position must be finite, got (" + num(nd.x) + ", " + num(nd.y) + ")");
    FLEXROCK_THROW_UNLESS(nd.y >= -kTipTolerance, node + " y must be >= 0 (at or above the base " +
                                                      "line), got " + num(nd.y));
    // a massless node (a mesh node the FE model carries no mass at) adds nothing but is allowed
    FLEXROCK_THROW_UNLESS(std::isfinite(nd.mass) && nd.mass >= 0.0,
                          node + " mass must be >= 0, got " + num(nd.mass));
    FLEXROCK_THROW_UNLESS(std::isfinite(nd.rotary_inertia) && nd.rotary_inertia >= 0.0,
                          node + " rotary_inertia must be >= 0, got " + num(nd.rotary_inertia));
    M += nd.mass;
    xm += nd.mass * nd.x;
    ym += nd.mass * nd.y;
  }
  FLEXROCK_THROW_UNLESS(M > 0.0, where + ": every node is massless; expected some mass > 0");
  const double xc = xm / M, h = ym / M;
  FLEXROCK_THROW_UNLESS(h > 0.0,
                        where + ": the c.g. must lie above the base line, got height " + num(h));
  FLEXROCK_THROW_UNLESS(std::isfinite(model.tip1_x) && std::isfinite(model.tip2_x) &&
                            model.tip1_x < xc && xc < model.tip2_x,
                        where + ": tipping points must straddle the c.g., tip1_x < " + num(xc) +
                            " < tip2_x, got tip1_x = " + num(model.tip1_x) +
                            ", tip2_x = " + num(model.tip2_x));

  // mode shapes: nodes x modes, both components the same size
  const bool rigid = model.phi_x.size() == 0 && model.phi_y.size() == 0;
  const Eigen::Index n = rigid ? 0 : model.phi_x.cols();
  if (!rigid) {
    FLEXROCK_THROW_UNLESS(
        model.phi_x.rows() == nn && model.phi_y.rows() == nn && model.phi_y.cols() == n,
        where + ": phi_x and phi_y must both be " + std::to_string(nn) +
            " x modes (one row per node), got phi_x " + std::to_string(model.phi_x.rows()) + "x" +
            std::to_string(model.phi_x.cols()) + " and phi_y " +
            std::to_string(model.phi_y.rows()) + "x" + std::to_string(model.phi_y.cols()));
    FLEXROCK_THROW_UNLESS(model.phi_x.allFinite() && model.phi_y.allFinite(),
                          where + ": phi_x and phi_y must be finite (a NaN or inf entry)");
  }
  const bool has_freq = model.frequencies.size() > 0, has_stiff = model.stiffness.size() > 0;
  if (n > 0) {
    FLEXROCK_THROW_UNLESS(has_freq != has_stiff,
                          where + ": give exactly one of frequencies and stiffness, got " +
                              (has_freq ? "both" : "neither"));
  } else {
    FLEXROCK_THROW_UNLESS(!has_freq && !has_stiff,
                          where + ": frequencies/stiffness given but there are no mode shapes");
  }

  VectorX m(nn);
  for (Eigen::Index k = 0; k < nn; ++k) m(k) = nodes[static_cast<std::size_t>(k)].mass;

  // with frequencies the modes must be mass-orthogonal, judged relative to the modal masses:
  // |m_ij| / sqrt(m_ii m_jj); shapes read from a printed table are re-orthogonalised
  MatrixX phx = model.phi_x, phy = model.phi_y;
  if (has_freq && n > 1 && model.frequencies.size() == n) {  // a wrong count: reported below
    auto inner = [&](Eigen::Index i, Eigen::Index j) {
      return phx.col(i).cwiseProduct(m).dot(phx.col(j)) +
             phy.col(i).cwiseProduct(m).dot(phy.col(j));
    };
    double worst = 0.0;
    Eigen::Index wi = 0, wj = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double mii = inner(i, i);
      const bool zero = phx.col(i).isZero(0.0) && phy.col(i).isZero(0.0);
      if (zero) continue;  // reported below with the shape
      FLEXROCK_THROW_UNLESS(mii > 0.0, where + ": mode " + idx(i) +
                                           " moves only massless nodes (modal mass 0); expected "
                                           "a shape that moves some mass");
      for (Eigen::Index j = 0; j < i; ++j) {
        const double mjj = inner(j, j);
        if (!(mjj > 0.0)) continue;
        const double rel = std::abs(inner(i, j)) / std::sqrt(mii * mjj);
        if (rel > worst) {
          worst = rel;
          wi = i;
          wj = j;
        }
      }
    }
    FLEXROCK_THROW_UNLESS(
        worst <= kPrintedOrthogonality,
        where + ": modes " + idx(wj) + " and " + idx(wi) +
            " are not mass-orthogonal: |m_ij| / sqrt(m_ii m_jj) = " + num(worst) +
            " (m_ij = sum m phi_i.phi_j over the nodes), more than the " +
            num(kPrintedOrthogonality) +
            " that printed shapes may carry; expected the modes of one mass matrix (give "
            "stiffness instead of frequencies for shapes that are not modes)");
    if (worst > kOrthogonality) {
      // Gram-Schmidt in the mass inner product, lowest mode first: mode i loses its
      // components along the modes before it, which the rounding of the printed values put there
      for (Eigen::Index i = 1; i < n; ++i) {
        for (Eigen::Index j = 0; j < i; ++j) {
          const double mjj = inner(j, j);
          if (!(mjj > 0.0)) continue;  // a zero shape, rejected below
          const double c = inner(i, j) / mjj;
          phx.col(i) -= c * phx.col(j);
          phy.col(i) -= c * phy.col(j);
        }
      }
      notes.push_back(where + ": modes " + idx(wj) + " and " + idx(wi) +
                      " were mass-orthogonal only to " + num(worst) +
                      " relative (|m_ij| / sqrt(m_ii m_jj)), as printed shapes are; the shapes "
                      "were re-orthogonalised (Gram-Schmidt with the nodal masses, lowest mode "
                      "first)");
    }
  }

  // rescale each mode so its largest nodal displacement is h: q_i = that displacement over h
  MatrixX px(nn, n), py(nn, n);
  VectorX scale(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const VectorX mag = (phx.col(i).cwiseAbs2() + phy.col(i).cwiseAbs2()).cwiseSqrt();
    const double big = mag.maxCoeff();
    FLEXROCK_THROW_UNLESS(big > 0.0, where + ": mode " + idx(i) + " shape is zero at every node");
    for (Eigen::Index k = 0; k < nn; ++k) {
      const LumpedNode& nd = nodes[static_cast<std::size_t>(k)];
      for (double tip : {model.tip1_x, model.tip2_x}) {
        const bool on_tip = std::hypot(nd.x - tip, nd.y) <= kTipTolerance;
        FLEXROCK_THROW_UNLESS(!on_tip || mag(k) <= kPinnedTolerance * big,
                              where + ": mode " + idx(i) + " moves node " + idx(k) +
                                  " at the tipping point x = " + num(tip) + " by " + num(mag(k)) +
                                  " (max " + num(big) +
                                  "): the modes must be pinned-base modes, zero at both "
                                  "tipping points");
      }
    }
    scale(i) = h / big;
    px.col(i) = scale(i) * phx.col(i);
    py.col(i) = scale(i) * phy.col(i);
  }

  // modal mass m_ij = sum m phi_i.phi_j for the rescaled shapes [kg m^2]
  const MatrixX modal_mass =
      px.transpose() * m.asDiagonal() * px + py.transpose() * m.asDiagonal() * py;

  // modal stiffness k_ij for the rescaled shapes [J]
  MatrixX kq = MatrixX::Zero(n, n);
  if (has_freq) {
    FLEXROCK_THROW_UNLESS(model.frequencies.size() == n,
                          where + ": frequencies must have " + std::to_string(n) +
                              " entries (one per mode), got " +
                              std::to_string(model.frequencies.size()));
    for (Eigen::Index i = 0; i < n; ++i) {
      const double w = model.frequencies(i);
      FLEXROCK_THROW_UNLESS(std::isfinite(w) && w > 0.0, where + ": frequency " + idx(i) +
                                                             " [rad/s] must be > 0, got " + num(w));
      // orthogonal modes: k = diag(omega_i^2 m_ii); m_ij below 1e-6 relative are not carried
      // into k
      kq(i, i) = w * w * modal_mass(i, i);
    }
    if (model.damping.kind == DampingKind::kModal) {
      for (Eigen::Index i = 1; i < n; ++i)
        FLEXROCK_THROW_UNLESS(model.frequencies(i) >= model.frequencies(i - 1),
                              where +
                                  ": with modal damping the modes must be in ascending "
                                  "frequency (Body assigns modal_ratios in that order), "
                                  "frequency " +
                                  idx(i) + " = " + num(model.frequencies(i)) + " < frequency " +
                                  idx(i - 1) + " = " + num(model.frequencies(i - 1)));
    }
  } else if (has_stiff) {
    const MatrixX& ks = model.stiffness;
    FLEXROCK_THROW_UNLESS(ks.rows() == n && ks.cols() == n,
                          where + ": stiffness must be " + std::to_string(n) + "x" +
                              std::to_string(n) + " (one row and column per mode), got " +
                              std::to_string(ks.rows()) + "x" + std::to_string(ks.cols()));
    FLEXROCK_THROW_UNLESS(ks.allFinite(), where + ": stiffness has a NaN or inf entry");
    const double big = ks.cwiseAbs().maxCoeff();
    const double asym = (ks - ks.transpose()).cwiseAbs().maxCoeff();
    FLEXROCK_THROW_UNLESS(asym <= kSymmetryTolerance * big,
                          where + ": stiffness must be symmetric, but k - k^T has an entry of " +
                              "size " + num(asym) + " (largest entry " + num(big) + ")");
    FLEXROCK_THROW_UNLESS(ks.llt().info() == Eigen::Success,
                          where +
                              ": stiffness must be positive definite (every mode needs "
                              "stiffness)");
    // u = phi_i q_i = (s_i phi_i)(q_i/s_i): k'_ij = s_i s_j k_ij, symmetrised
    kq = scale.asDiagonal() * (0.5 * (ks + ks.transpose())) * scale.asDiagonal();
  }

  if (model.damping.kind == DampingKind::kModal)
    FLEXROCK_THROW_UNLESS(model.damping.modal_ratios.size() == n,
                          where + ": modal damping needs one ratio per mode (" + std::to_string(n) +
                              "), got " + std::to_string(model.damping.modal_ratios.size()));

  // the integrals of the paper as sums over the nodes, rho0 from the c.g.; node rotations are
  // not part of the mode shapes, so a node's rotary inertia adds to zeta2 only
  BodyParameters p;
  p.mass = M;
  p.height = h;
  p.b1 = xc - model.tip1_x;
  p.b2 = model.tip2_x - xc;
  p.gravity = model.gravity;
  p.damping = model.damping;
  const double mh2 = M * h * h;
  VectorX rx(nn), ry(nn);
  double inertia = 0.0;
  for (Eigen::Index k = 0; k < nn; ++k) {
    const LumpedNode& nd = nodes[static_cast<std::size_t>(k)];
    rx(k) = nd.x - xc;
    ry(k) = nd.y - h;
    inertia += nd.mass * (rx(k) * rx(k) + ry(k) * ry(k)) + nd.rotary_inertia;
  }
  p.zeta2 = inertia / mh2;
  p.mu = modal_mass / mh2;
  p.kappa = kq / (M * model.gravity * h);
  p.gamma = (px.transpose() * m.asDiagonal() * py - py.transpose() * m.asDiagonal() * px) / mh2;
  p.psi_x = px.transpose() * m / (M * h);
  p.psi_y = py.transpose() * m / (M * h);
  const VectorX mrx = m.cwiseProduct(rx), mry = m.cwiseProduct(ry);
  p.delta = (px.transpose() * mrx + py.transpose() * mry) / mh2;
  p.beta = (py.transpose() * mrx - px.transpose() * mry) / mh2;
  return p;
}

BodyParameters oscillator_on_slab(double top_mass, double frequency_hz, double base_mass,
                                  double height, double base_width, double damping_ratio) {
  constexpr const char* kWhere = "oscillator_on_slab";
  require_positive(kWhere, "top_mass", top_mass, "[kg]");
  require_positive(kWhere, "frequency_hz", frequency_hz, "[Hz]");
  // a slab is needed: with base_mass = 0 the body is a point mass at its c.g. (zeta2 = 0)
  require_positive(kWhere, "base_mass", base_mass, "[kg]");
  require_positive(kWhere, "height", height, "[m]");
  require_positive(kWhere, "base_width", base_width, "[m]");
  require_damping_ratio(kWhere, damping_ratio);

  const double m = top_mass, m0 = base_mass, H = height;
  const double M = m + m0, h = m * H / M, b = 0.5 * base_width;
  const double w = 2.0 * std::numbers::pi * frequency_hz;
  const double k = m * w * w;  // [N/m] lateral spring
  BodyParameters p;
  p.mass = M;
  p.height = h;
  p.b1 = p.b2 = b;
  // top mass at H - h above the c.g., slab h below it with I = m0 (2b)^2/12 about its centre
  p.zeta2 = (m * (H - h) * (H - h) + m0 * h * h + m0 * b * b / 3.0) / (M * h * h);
  // one mode: phi = h i at the top mass, so q = u/h and the strain energy is k h^2 q^2/2
  p.mu = MatrixX::Constant(1, 1, m / M);
  p.kappa = MatrixX::Constant(1, 1, k * h / (M * p.gravity));
  p.gamma = MatrixX::Zero(1, 1);
  p.psi_x = VectorX::Constant(1, m / M);
  p.psi_y = VectorX::Zero(1);
  p.delta = VectorX::Zero(1);
  p.beta = VectorX::Constant(1, -m * (H - h) / (M * h));
  p.damping = modal_damping(1, damping_ratio);
  return p;
}

BodyParameters uniform_cantilever(double height, double width, double mass_per_length,
                                  double bending_stiffness, int modes, double base_mass,
                                  double damping_ratio) {
  constexpr const char* kWhere = "uniform_cantilever";
  require_positive(kWhere, "height", height, "[m]");
  require_positive(kWhere, "width", width, "[m]");
  require_positive(kWhere, "mass_per_length", mass_per_length, "[kg/m]");
  require_positive(kWhere, "bending_stiffness", bending_stiffness, "EI [N m^2]");
  FLEXROCK_THROW_UNLESS(modes >= 1 && modes <= kMaxBuilderModes,
                        std::string(kWhere) + ": modes must be in [1, " +
                            std::to_string(kMaxBuilderModes) + "], got " + std::to_string(modes));
  require_non_negative(kWhere, "base_mass", base_mass, "[kg]");
  require_damping_ratio(kWhere, damping_ratio);

  const double L = height, w = width, mbar = mass_per_length, EI = bending_stiffness;
  const double M = mbar * L + base_mass, h = 0.5 * mbar * L * L / M, mh2 = M * h * h;
  const int n = modes;
  const int panels = 4 * n + 4;  // >= 4 panels per half-wave of the highest product

  // modes normalised to tip displacement h: phi_i(y) = c_i shape(b_i y), q_i = tip u / h
  std::vector<CantileverMode> mode;
  VectorX b(n), c(n);
  for (int i = 0; i < n; ++i) {
    mode.emplace_back(cantilever_root(i + 1));
    b(i) = mode.back().X / L;
    c(i) = h / mode.back().shape(mode.back().X);
  }
  auto phi = [&](int i, double y) {
    return c(i) * mode[static_cast<std::size_t>(i)].shape(b(i) * y);
  };
  auto phi2 = [&](int i, double y) {
    return c(i) * b(i) * b(i) * mode[static_cast<std::size_t>(i)].curvature(b(i) * y);
  };

  BodyParameters p;
  p.mass = M;
  p.height = h;
  p.b1 = p.b2 = 0.5 * w;
  // beam: a uniform rectangle of width w (mbar w^2/12 per length); plate: thin, at y = 0
  const double beam_inertia =
      integrate([&](double y) { return mbar * ((y - h) * (y - h) + w * w / 12.0); }, L, 4);
  p.zeta2 = (beam_inertia + base_mass * (h * h + w * w / 12.0)) / mh2;

  // phi_i = phi_i(y) i along the centre line rho0 = (0, y - h): gamma = psi_y = delta = 0
  p.mu = MatrixX::Zero(n, n);
  p.kappa = MatrixX::Zero(n, n);
  p.gamma = MatrixX::Zero(n, n);
  p.psi_x = VectorX::Zero(n);
  p.psi_y = VectorX::Zero(n);
  p.delta = VectorX::Zero(n);
  p.beta = VectorX::Zero(n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j <= i; ++j) {
      const double mij =
          integrate([&](double y) { return mbar * phi(i, y) * phi(j, y); }, L, panels);
      const double kij =
          integrate([&](double y) { return EI * phi2(i, y) * phi2(j, y); }, L, panels);
      p.mu(i, j) = p.mu(j, i) = mij / mh2;
      p.kappa(i, j) = p.kappa(j, i) = kij / (M * p.gravity * h);
    }
    p.psi_x(i) = integrate([&](double y) { return mbar * phi(i, y); }, L, panels) / (M * h);
    p.beta(i) = -integrate([&](double y) { return mbar * (y - h) * phi(i, y); }, L, panels) / mh2;
  }
  p.damping = modal_damping(n, damping_ratio);
  return p;
}

}  // namespace flexrock

// ---------------------------------------------------------------------------------------------
// the table of body types

namespace flexrock {

namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

// a number that must be given, > 0
BodyKey positive(const char* name, const char* unit, const char* doc) {
  return {name, unit, BodyKeyValue::kNumber, BodyKeyRule::kPositive, true, kNone, nullptr, doc};
}

// a number >= 0 with a default
BodyKey nonnegative_or(const char* name, const char* unit, double fixed, const char* doc) {
  return {name, unit, BodyKeyValue::kNumber, BodyKeyRule::kNonnegative, false, fixed, nullptr, doc};
}

// a number > 0 with a default
BodyKey positive_or(const char* name, const char* unit, double fixed, const char* doc) {
  return {name, unit, BodyKeyValue::kNumber, BodyKeyRule::kPositive, false, fixed, nullptr, doc};
}

// a finite number that must be given
BodyKey number(const char* name, const char* unit, const char* doc) {
  return {name, unit, BodyKeyValue::kNumber, BodyKeyRule::kFinite, true, kNone, nullptr, doc};
}

// an integer >= 1 with a default
BodyKey count_or(const char* name, double fixed, const char* doc) {
  return {name, "-", BodyKeyValue::kInteger, BodyKeyRule::kPositive, false, fixed, nullptr, doc};
}

// an array, matrix or path, read by the case loader's reader of the type
BodyKey data(const char* name, const char* unit, BodyKeyValue value, const char* default_text,
             const char* doc) {
  return {name, unit, value, BodyKeyRule::kFinite, false, kNone, default_text, doc};
}

// the damping keys of `paper` and `lumped`
void add_damping(std::vector<BodyKey>& keys) {
  keys.push_back(data("damping_ratios", "-", BodyKeyValue::kArray, "none",
                      "modal damping: one ratio a pinned-base mode, ascending frequency"));
  keys.push_back(data("rayleigh_mass", "1/s", BodyKeyValue::kNumber, "0",
                      "a of Rayleigh damping C = a mu + b K (instead of `damping_ratios`), >= 0"));
  keys.push_back(
      data("rayleigh_stiffness", "s", BodyKeyValue::kNumber, "0", "b of Rayleigh damping, >= 0"));
}

const char* const kGravityDoc = "g";

AxisymmetricBody body_of_revolution(const BodyArgs& a) {
  AxisymmetricBody b;
  b.mass = a.at("mass");
  b.height = a.at("cg_height");
  b.radius = a.at("base_radius");
  b.inertia_diameter = a.at("inertia_diameter");
  b.inertia_axis = a.at("inertia_axis");
  validate(b);
  return b;
}

std::vector<BodyKind> make_body_kinds() {
  std::vector<BodyKind> kinds;
  kinds.push_back(
      {"rigid_block",
       "rigid_block",
       {positive("width", "m", "full width of the footprint"),
        positive("height", "m", "full height"), positive("mass", "kg", "mass")},
       [](const BodyArgs& a) { return rigid_block(a.at("width"), a.at("height"), a.at("mass")); },
       "uniform rigid rectangular block"});
  kinds.push_back({"rigid_body",
                   "rigid_body",
                   {positive("mass", "kg", "M"),
                    positive("inertia_cg", "kg m^2", "rotary inertia about the c.g."),
                    positive("height", "m", "h, c.g. above the base"),
                    positive("b1", "m", "c.g. to tipping point 1 (horizontal)"),
                    positive("b2", "m", "c.g. to tipping point 2")},
                   [](const BodyArgs& a) {
                     return rigid_body(a.at("mass"), a.at("inertia_cg"), a.at("height"), a.at("b1"),
                                       a.at("b2"));
                   },
                   "general rigid body"});
  std::vector<BodyKey> paper = {
      positive("mass", "kg", "M"),
      positive("height", "m", "h, c.g. above the base"),
      positive("b1", "m", "c.g. to tipping point 1 (horizontal)"),
      positive("b2", "m", "c.g. to tipping point 2"),
      positive("zeta2", "-", "zeta^2 = I_zz/(M h^2) about the c.g."),
      positive_or("gravity", "m/s^2", kStandardGravity, kGravityDoc),
      data("kappa", "-", BodyKeyValue::kMatrix, "none (rigid)",
           "n x n stiffness, `[[...], ...]`, symmetric positive definite; n, the number of "
           "modes, is its size"),
      data("mu", "-", BodyKeyValue::kMatrix, "required with `kappa`",
           "n x n modal mass, symmetric positive definite"),
      data("gamma", "-", BodyKeyValue::kMatrix, "zeros", "n x n, antisymmetric"),
      data("psi_x", "-", BodyKeyValue::kArray, "zeros", "n values"),
      data("psi_y", "-", BodyKeyValue::kArray, "zeros", "n values"),
      data("delta", "-", BodyKeyValue::kArray, "zeros", "n values"),
      data("beta", "-", BodyKeyValue::kArray, "zeros", "n values")};
  add_damping(paper);
  kinds.push_back({"paper", "", std::move(paper), nullptr,
                   "the paper's dimensionless parameters directly (Moran & McLennan; see "
                   "docs/theory.md)"});
  std::vector<BodyKey> lumped = {
      number("tip1_x", "m", "x of tipping point 1, the left edge"),
      number("tip2_x", "m", "x of tipping point 2, the right edge, > `tip1_x`"),
      positive_or("gravity", "m/s^2", kStandardGravity, kGravityDoc),
      data("nodes", "m, m, kg, kg m^2", BodyKeyValue::kMatrix, "one of `nodes`, `nodes_file`",
           "`[[x, y, mass], [x, y, mass, rotary_inertia], ...]`"),
      data("nodes_file", "", BodyKeyValue::kPath, "",
           "table file of the nodes, columns named in a header row (below)"),
      data("frequencies_hz", "Hz", BodyKeyValue::kArray, "one of these two",
           "natural frequencies of the modes (n values)"),
      data("stiffness", "N m", BodyKeyValue::kMatrix, "",
           "n x n modal stiffness for the shapes as given"),
      data("phi_x", "m", BodyKeyValue::kMatrix, "one of inline or `shapes_file`",
           "one row a node, one value a mode: `[[phi_1, phi_2], ...]`"),
      data("phi_y", "m", BodyKeyValue::kMatrix, "", "the same, vertical components"),
      data("shapes_file", "m", BodyKeyValue::kPath, "",
           "table file of the mode shapes as an FE program prints them (below)")};
  add_damping(lumped);
  kinds.push_back({"lumped", "", std::move(lumped), nullptr,
                   "a lumped-mass modal model as a finite-element program exports it (below)"});
  kinds.push_back(
      {"oscillator_on_slab",
       "oscillator_on_slab",
       {positive("top_mass", "kg", "the oscillating mass"),
        positive("frequency_hz", "Hz", "its natural frequency on a fixed base"),
        positive("base_mass", "kg", "the slab"),
        positive("height", "m", "the top mass above the base"),
        positive("base_width", "m", "full width of the slab (between the tipping points)"),
        nonnegative_or("damping_ratio", "-", 0.0, "of the mode")},
       [](const BodyArgs& a) {
         return oscillator_on_slab(a.at("top_mass"), a.at("frequency_hz"), a.at("base_mass"),
                                   a.at("height"), a.at("base_width"), a.at("damping_ratio"));
       },
       "a top mass on a lateral spring above a rigid base slab (one mode)"});
  kinds.push_back(
      {"uniform_cantilever",
       "uniform_cantilever",
       {positive("height", "m", "length of the cantilever"),
        positive("width", "m", "full width, between the tipping points"),
        positive("mass_per_length", "kg/m", "mass of the cantilever a metre"),
        positive("bending_stiffness", "N m^2", "EI"),
        count_or("modes", 1.0, "clamped-free bending modes kept"),
        nonnegative_or("base_mass", "kg", 0.0, "rigid base plate"),
        nonnegative_or("damping_ratio", "-", 0.0, "of every mode")},
       [](const BodyArgs& a) {
         return uniform_cantilever(a.at("height"), a.at("width"), a.at("mass_per_length"),
                                   a.at("bending_stiffness"), static_cast<int>(a.at("modes")),
                                   a.at("base_mass"), a.at("damping_ratio"));
       },
       "a uniform flexible cantilever (tank, stack, column) clamped to a rigid base plate "
       "standing on its two edges"});
  kinds.push_back(
      {"rocking_frame",
       "rocking_frame",
       {positive("column_width", "m", "full width of a column's footprint"),
        positive("column_height", "m", "full height of a column"),
        positive("column_mass", "kg", "mass of one column"),
        {"count", "-", BodyKeyValue::kInteger, BodyKeyRule::kPositive, false, 2.0,
         "2, integer >= 2", "number of equal columns"},
        nonnegative_or("beam_mass", "kg", 0.0, "the freely supported rigid cap beam")},
       [](const BodyArgs& a) {
         RockingFrame f;
         f.column_width = a.at("column_width");
         f.column_height = a.at("column_height");
         f.column_mass = a.at("column_mass");
         f.count = static_cast<int>(a.at("count"));
         f.beam_mass = a.at("beam_mass");
         return frame_equivalent_body(f);
       },
       "equal free-standing rigid columns capped by a freely supported rigid beam, run as its "
       "equivalent rigid body (docs/theory.md §25)"});
  // bodies of revolution: in the plane their section through the axis (planar_equivalent); with a
  // record pair `flexrock run` runs them in 3D (docs/theory.md §27, axisymmetric_body())
  kinds.push_back(
      {"cylinder",
       "cylinder",
       {positive("radius", "m", "outer radius of the base"), positive("height", "m", "full height"),
        positive("mass", "kg", "mass"),
        nonnegative_or("inner_radius", "m", 0.0, "bore of a hollow cylinder, < radius")},
       [](const BodyArgs& a) {
         return planar_equivalent(
             uniform_cylinder(a.at("radius"), a.at("height"), a.at("mass"), a.at("inner_radius")));
       },
       "uniform solid or hollow circular cylinder (a body of revolution: 3D with a "
       "record pair)"});
  kinds.push_back(
      {"body_of_revolution",
       "body_of_revolution",
       {positive("mass", "kg", "M"), positive("cg_height", "m", "h, c.g. above the base centre"),
        positive("base_radius", "m", "R, radius of the base rim"),
        positive("inertia_diameter", "kg m^2", "A, about a diameter through the c.g."),
        positive("inertia_axis", "kg m^2", "C, about the axis (C <= 2 A)")},
       [](const BodyArgs& a) { return planar_equivalent(body_of_revolution(a)); },
       "any rigid body of revolution on a flat circular base (3D with a record pair)"});
  return kinds;
}

std::string join_names(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

}  // namespace

double BodyArgs::at(std::string_view name) const {
  const auto it = keys.find(name);
  FLEXROCK_DEMAND(it != keys.end());
  return it->second;
}

std::optional<AxisymmetricBody> axisymmetric_body(std::string_view type, const BodyArgs& args) {
  if (type == "cylinder") {
    return uniform_cylinder(args.at("radius"), args.at("height"), args.at("mass"),
                            args.at("inner_radius"));
  }
  if (type == "body_of_revolution") return body_of_revolution(args);
  return std::nullopt;
}

const std::vector<BodyKind>& body_kinds() {
  static const std::vector<BodyKind> kinds = make_body_kinds();
  return kinds;
}

std::vector<std::string> body_kind_names() {
  std::vector<std::string> v;
  for (const BodyKind& k : body_kinds()) v.emplace_back(k.name);
  return v;
}

const BodyKind& body_kind(std::string_view name) {
  for (const BodyKind& k : body_kinds()) {
    if (name == k.name) return k;
  }
  throw InputError("expected a body type, one of: " + join_names(body_kind_names()) + "; got \"" +
                   std::string(name) + "\"");
}

BodyParameters make_body(const BodyKind& kind, BodyArgs args) {
  FLEXROCK_THROW_UNLESS(kind.make, std::string(kind.name) +
                                       ": its keys are not all numbers; build it from "
                                       "BodyParameters or a LumpedModel");
  std::vector<std::string> names;
  for (const BodyKey& k : kind.keys) names.emplace_back(k.name);
  for (const auto& [name, value] : args.keys) {
    FLEXROCK_THROW_UNLESS(
        std::find(names.begin(), names.end(), name) != names.end(),
        std::string(kind.name) + ": unknown key '" + name + "'; expected " + join_names(names));
  }
  for (const BodyKey& k : kind.keys) {
    const auto it = args.keys.find(k.name);
    if (it == args.keys.end()) {
      FLEXROCK_THROW_UNLESS(!k.required,
                            std::string(kind.name) + ": " + k.name + " [" + k.unit + "] missing");
      args.keys.emplace(k.name, k.fixed);
      continue;
    }
    if (k.value == BodyKeyValue::kInteger) {
      const double v = it->second;
      FLEXROCK_THROW_UNLESS(
          std::isfinite(v) && v >= 1.0 && v == std::floor(v) && v <= 1e9,
          std::string(kind.name) + ": " + k.name + " must be an integer >= 1, got " + num(v));
    }
  }
  return kind.make(args);
}

std::string default_text(const BodyKey& key) {
  if (key.default_text) return key.default_text;
  const char* rule = key.value == BodyKeyValue::kInteger     ? ", integer >= 1"
                     : key.rule == BodyKeyRule::kPositive    ? ", > 0"
                     : key.rule == BodyKeyRule::kNonnegative ? ", >= 0"
                                                             : "";
  return (key.required ? std::string("required") : format_number(key.fixed)) + rule;
}

}  // namespace flexrock
