// SPDX-License-Identifier: BSD-3-Clause
// Bodies from what engineers have: dimensions, a finite-element model's modal output, or a
// standard idealisation. Each builder returns the paper's parameters (BodyParameters); pass them
// to Body to validate. No files here: readers live in io/.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "flexrock/model/axisymmetric_body.hpp"
#include "flexrock/model/body.hpp"

namespace flexrock {

/// Uniform rigid rectangular block of full `width` and full `height` [m], mass [kg].
BodyParameters rigid_block(double width, double height, double mass);

/// The same body taken as rigid (a case file's `rigid = true`): M, h, b1, b2, zeta^2 and g kept,
/// every modal term (mu, kappa, gamma, psi, delta, beta, damping) dropped.
BodyParameters taken_rigid(const BodyParameters& body);

/// General rigid body: mass M [kg], rotary inertia about the c.g. I_cg [kg m^2], c.g. height h
/// and distances b1, b2 [m] from the c.g. to the tipping points.
BodyParameters rigid_body(double mass, double inertia_cg, double height, double b1, double b2);

/// One node of a lumped-mass model, in a frame with the base line at y = 0.
struct LumpedNode {
  double x = 0.0;               // [m]
  double y = 0.0;               // [m] height above the base line
  double mass = 0.0;            // [kg]
  double rotary_inertia = 0.0;  // [kg m^2] about the node; adds to zeta2 only (node rotations
                                // are not part of the mode shapes)
};

/// A lumped-mass modal model as a finite-element program exports it. The mode shapes are the
/// pinned-base modes (both tipping points held), in any normalisation; they must vanish at the
/// tipping points (nodes placed there must have zero shape). Nodes may be massless (mass 0: mesh
/// nodes the model carries no mass at); the total mass must be > 0.
struct LumpedModel {
  std::vector<LumpedNode> nodes;
  double tip1_x = 0.0;  // [m] left tipping point (edge 1) on the base line
  double tip2_x = 0.0;  // [m] right tipping point (edge 2)
  MatrixX phi_x;        // [m] nodes x modes, horizontal mode shape components
  MatrixX phi_y;        // [m] nodes x modes, vertical components
  VectorX frequencies;  // [rad/s] natural frequencies of the modes (or give `stiffness`)
  MatrixX stiffness;    // [N m] modal stiffness k_ij for the shapes as given (alternative)
  Damping damping;      // material damping of the modes
  double gravity = kStandardGravity;
};

/// Every integral of the paper from the lumped model: the shapes are rescaled so that q_i is
/// the largest displacement of mode i over h (the sign of each shape is kept). With
/// `frequencies`, k_ii = omega_i^2 m_ii and k_ij = 0: the modes must be mass-orthogonal,
/// judged relative to the modal masses, |m_ij| / sqrt(m_ii m_jj) with m_ij = sum m phi_i.phi_j.
/// Up to 1e-6 the shapes are taken as given; up to 1e-2 (shapes printed to a few significant
/// digits) they are re-orthogonalised by Gram-Schmidt in the mass inner product, lowest mode
/// first, and a note says so; above 1e-2 they are rejected with the figure. With modal damping
/// the frequencies must ascend. Without shapes the body is rigid. Throws InputError for
/// inconsistent data (sizes, shapes at the tipping points, tipping points not straddling the
/// c.g., non-orthogonal modes with `frequencies`, a mode that moves no mass).
BodyParameters from_lumped_model(const LumpedModel& model);

/// As above; `notes` receives what was changed in the data (re-orthogonalised shapes).
BodyParameters from_lumped_model(const LumpedModel& model, std::vector<std::string>& notes);

/// An elastic oscillator on a rocking base slab: a top mass on a lateral spring at `height`
/// above a rigid base slab of mass `base_mass` and full width `base_width` (uniform, thin).
/// One mode: the top mass's horizontal displacement. `base_mass` must be > 0 (a massless slab
/// leaves no rotary inertia about the c.g.).
BodyParameters oscillator_on_slab(double top_mass, double frequency_hz, double base_mass,
                                  double height, double base_width, double damping_ratio = 0.0);

/// A uniform flexible cantilever (tank, stack, column) of `height` and full `width`, mass per
/// length [kg/m] and bending stiffness EI [N m^2], clamped to a rigid base plate of mass
/// `base_mass` standing on its two edges, with `modes` clamped-free bending modes.
BodyParameters uniform_cantilever(double height, double width, double mass_per_length,
                                  double bending_stiffness, int modes, double base_mass = 0.0,
                                  double damping_ratio = 0.0);

// ---------------------------------------------------------------------------------------------
// The table of body types: one entry a body.type, read by the case loader (and so by the study
// loaders, which read bodies through it), the Python keyword functions, `flexrock check` and the
// generated key reference of docs/case-file.md. A body type whose keys are all numbers is one
// entry here and its builder above.

/// What a key of a body type holds.
enum class BodyKeyValue {
  kNumber,   // a finite number, checked by its rule
  kInteger,  // an integer >= 1
  kArray,    // an array of numbers
  kMatrix,   // an array of rows of numbers
  kPath,     // a path to a file, relative to the case file
};

/// How a number key is checked.
enum class BodyKeyRule {
  kFinite,       // any finite number
  kPositive,     // > 0
  kNonnegative,  // >= 0
};

/// One key of a body type.
struct BodyKey {
  const char* name;  // key in a case file and keyword in Python
  const char* unit;  // "m", "kg m^2", "-"
  BodyKeyValue value;
  BodyKeyRule rule;          // numbers only
  bool required;             // no default: the key must be given (numbers)
  double fixed;              // default of a number that is not required
  const char* default_text;  // the default as the docs state it; nullptr: from the fields above
  const char* doc;           // one line: what the key means
};

/// The numbers a body type is made from, by key name, in the units of its keys.
struct BodyArgs {
  std::map<std::string, double, std::less<>> keys;
  /// The value of key `name` (given or defaulted by make_body); FLEXROCK_DEMAND if absent.
  double at(std::string_view name) const;
};

/// One body type.
struct BodyKind {
  const char* name;      // body.type in case files ("rigid_block")
  const char* function;  // the builder of this header, the Python function ("rigid_block")
  std::vector<BodyKey> keys;
  /// The builder, from the keys' values; nullptr: keys that are not all numbers (arrays, files),
  /// which the case loader reads with its own reader of this type.
  BodyParameters (*make)(const BodyArgs& args);
  const char* doc;  // one line: what the body is
};

/// Every body type, in the order the docs list them.
const std::vector<BodyKind>& body_kinds();

/// The names of the body types, in the table's order.
std::vector<std::string> body_kind_names();

/// The body type of a name; throws InputError listing the known names.
const BodyKind& body_kind(std::string_view name);

/// Makes a body type with a builder from `args`: fills the defaults of keys not given, refuses
/// missing required keys, keys the type does not have and integer keys that are not whole
/// numbers >= 1; the builder checks the values. Throws InputError naming the key.
BodyParameters make_body(const BodyKind& kind, BodyArgs args);

/// The 3D body of a body type that is a body of revolution ("cylinder", "body_of_revolution"),
/// from the same keys its planar section is made from (`args` with its defaults filled, as
/// make_body fills them); nullopt for the other types. Throws InputError for bad values.
std::optional<AxisymmetricBody> axisymmetric_body(std::string_view type, const BodyArgs& args);

/// The default of a key as the docs state it ("required, > 0", "0", "none").
std::string default_text(const BodyKey& key);

}  // namespace flexrock
