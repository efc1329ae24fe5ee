// write_inp: an Abaqus / CalculiX input file (.inp) of a shape's quad mesh, as 4-node
// shell elements (S4), for a solver deck to *INCLUDE or to extend:
//
//   ** TemplateQuad mesh: 15 nodes, 8 S4 elements, 2 faces
//   *NODE, NSET=NALL
//   1, 0, 0, 0                      node k + 1 is ShapeMesh node k (1-based ids)
//   ...
//   *ELEMENT, TYPE=S4, ELSET=FACE3  one block per face record: element set FACE<k>
//   1, 1, 2, 5, 4                   holds the quads of face k (k as in the record)
//   ...
//   *ELSET, ELSET=EALL, GENERATE    all elements
//   1, 8, 1
//
// Element k + 1 is ShapeMesh quad k (ids continuous from 1 over the faces), its nodes
// in the quad's (counter-clockwise) order, so the shell normal is the face's normal.
// Coordinates are the shortest text that reads back to the same double, or, where that
// is wider than CalculiX's 20-character field, the most digits that fit. A face record
// with no quads gets no block; refused faces are listed as comments. Lines stay under
// CalculiX's 132 characters.
#pragma once

#include <ostream>
#include <string>

#include "core/mesh/shape_mesh.h"

namespace tquad {

// Throws std::invalid_argument for an inconsistent ShapeMesh (see shape_mesh_check.h)
// and std::logic_error for a non-finite coordinate.
void write_inp(std::ostream& out, const ShapeMesh& mesh);

// Writes PATH atomically (see atomic_file_writer.h).
void write_inp_file(const std::string& path, const ShapeMesh& mesh);

}  // namespace tquad
