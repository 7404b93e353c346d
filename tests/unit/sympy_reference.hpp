// SPDX-License-Identifier: BSD-3-Clause
// Reading tools/derive/derive.py's reference (sympy_reference.json) into the engine's types: the
// vectors, matrices and body parameters of its cases. Shared by the tests that compare with it.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>

#include "flexrock/model/body.hpp"

namespace flexrock::sympy_reference {

using json = nlohmann::json;

inline VectorX vec(const json& j) {
  VectorX v(static_cast<Eigen::Index>(j.size()));
  for (std::size_t i = 0; i < j.size(); ++i) v(static_cast<Eigen::Index>(i)) = j[i].get<double>();
  return v;
}

inline MatrixX mat(const json& j, Eigen::Index n) {
  MatrixX m(n, n);
  for (Eigen::Index r = 0; r < n; ++r)
    for (Eigen::Index c = 0; c < n; ++c)
      m(r, c) = j[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)].get<double>();
  return m;
}

// a reference case's body ("n", "params") under gravity g
inline BodyParameters params_of(const json& c, double g) {
  const auto n = c["n"].get<Eigen::Index>();
  const json& p = c["params"];
  BodyParameters b;
  b.mass = p["M"];
  b.height = p["h"];
  b.b1 = p["b1"];
  b.b2 = p["b2"];
  b.zeta2 = p["zeta2"];
  b.mu = mat(p["mu"], n);
  b.kappa = mat(p["kappa"], n);
  b.gamma = mat(p["gamma"], n);
  b.psi_x = vec(p["psi_x"]);
  b.psi_y = vec(p["psi_y"]);
  b.delta = vec(p["delta"]);
  b.beta = vec(p["beta"]);
  b.gravity = g;
  return b;
}

}  // namespace flexrock::sympy_reference
