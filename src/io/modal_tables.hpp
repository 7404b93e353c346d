// SPDX-License-Identifier: BSD-3-Clause
// Node tables and mode-shape tables as finite-element programs print them: columns are found by
// the names in a header row (node, x, y, mass, rotary_inertia; UX/UY, U.U1/U.U2, phi_x/phi_y or
// phi_x_<k>/phi_y_<k> for the shapes), so a node-id column or extra columns (UZ, USUM) cannot
// shift the values. Banners, page headers and summary lines around the tables are skipped.
// Internal to flexrock::io.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "flexrock/core/types.hpp"
#include "flexrock/model/builders.hpp"

namespace flexrock::io::detail {

/// The nodes of a lumped model from a CSV or whitespace table. With a header row the columns
/// are taken by name (node, x, y, mass, rotary_inertia; units in brackets allowed, case and
/// '_' '.' ignored); without one the file must have exactly the three columns x, y, mass.
struct NodeTable {
  std::vector<LumpedNode> nodes;
  std::vector<std::string> ids;    // node labels, one a node; empty without a node column
  std::vector<std::size_t> lines;  // the line of each node in the file
};
NodeTable read_node_table(const std::string& path);

/// Mode shapes, nodes x modes. A file holds either one table with phi_x_<k>, phi_y_<k> columns
/// for every mode k = 1..n, or one table a mode with an x and a y component column (UX/UY as
/// ANSYS PRNSOL lists them, U.U1/U.U2 as an Abaqus field report writes them, U1/U2, phi_x/phi_y).
/// A table whose node labels continue the previous one (a page break) continues its mode.
/// Without a header row the file must have exactly 2 n columns phi_x_1, phi_y_1, ... .
struct ShapeTable {
  std::vector<std::string> ids;    // node labels of the rows; empty without a node column
  std::vector<std::size_t> lines;  // the line of each row (of the first mode)
  MatrixX phi_x, phi_y;            // rows x modes
};
ShapeTable read_shape_table(const std::string& path, Eigen::Index modes);

/// The shapes of `shapes` in the order of `nodes`: by node label when both files have one
/// (shape rows of nodes that are not in the nodes table are left out: they carry no mass), else
/// row by row. Throws InputError naming the node that has no shape.
void match_shapes(const NodeTable& nodes, const std::string& nodes_path, const ShapeTable& shapes,
                  const std::string& shapes_path, MatrixX& phi_x, MatrixX& phi_y);

}  // namespace flexrock::io::detail
