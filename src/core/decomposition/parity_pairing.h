// make_nodes_even: the parity fix shared by the shape's interval assignment (nodes are
// faces, curves are CAD edges) and a face's cut counts (nodes are patches, curves are
// cuts). Each node's total of curve counts must be even. Counts change by one in
// units: a chain of curves kept equal, or a single curve; a unit flips the parity of
// the nodes that hold an odd number of its curves (a face holding two edges of a
// chain, or a seam twice, keeps its parity). Odd nodes are paired along shortest
// paths of the graph whose edges are the units flipping exactly two nodes, and every
// unit on a path changes (the nodes inside a path flip twice and stay even). A node
// left without a partner changes a unit that flips it alone, the one with the largest
// summed goal (it changes least, relatively); if it has none, the path to the nearest
// node that has one and that unit change.
#pragma once

#include <vector>

namespace tquad {

struct ParityUnit {
  std::vector<int> curves;
  std::vector<int> flipped;  // the nodes whose parity a change of the unit flips
};

// `odd`: per node, whether its total is odd now. Changes `count` (per curve) by +1 or
// -1 per unit changed, whichever keeps nearer the goals (count_fitting.h), never
// below `minimum`. Returns -1 when every node is even, else the first odd node that
// could not be made even (the others may have been changed).
int make_nodes_even(std::vector<char> odd, const std::vector<ParityUnit>& units, const std::vector<double>& goal,
                    const std::vector<int>& minimum, std::vector<int>& count);

}  // namespace tquad
