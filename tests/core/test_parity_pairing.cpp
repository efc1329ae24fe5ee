// make_nodes_even: every node's total made even by changing units of curves.
#include <gtest/gtest.h>

#include <vector>

#include "core/decomposition/parity_pairing.h"

namespace tquad {
namespace {

TEST(ParityPairing, TwoOddNodesArePairedAlongTheirPath) {
  // 0 - 1 - 2 in a row (units 0 and 1 between them), a unit of node 0's own (2),
  // nodes 0 and 2 odd: the path changes, the own unit does not.
  const std::vector<ParityUnit> units{{{0}, {0, 1}}, {{1}, {1, 2}}, {{2}, {0}}};
  std::vector<int> count{3, 4, 4};
  std::vector<char> odd{1, 0, 1};
  const std::vector<double> goal{3.0, 4.0, 4.0};
  EXPECT_EQ(make_nodes_even(odd, units, goal, {1, 1, 1}, count), -1);
  EXPECT_NE(count[0], 3);
  EXPECT_NE(count[1], 4);
  EXPECT_EQ(count[2], 4);
}

TEST(ParityPairing, ALoneOddNodeReachesTheNearestUnitOfAnotherNodesOwn) {
  // 0 - 1 - 2 in a row, node 0 odd and alone, and only node 2 has a unit of its own
  // (an edge to a face left out of the mesh): the path and that unit change, so
  // every node ends even. It used to be refused as impossible.
  // Node 0 holds curves 0 and 3 (3 + 2: odd), node 1 curves 0 and 1, node 2 curves 1
  // and 2; curve 3 is in no unit (it may not change: a chain's, say).
  const std::vector<ParityUnit> units{{{0}, {0, 1}}, {{1}, {1, 2}}, {{2}, {2}}};
  const std::vector<int> count{3, 5, 3, 2};
  const std::vector<double> goal{3.0, 5.0, 3.0, 2.0};
  std::vector<int> changed = count;
  ASSERT_EQ(make_nodes_even({1, 0, 0}, units, goal, {1, 1, 1, 1}, changed), -1);
  EXPECT_NE(changed[0], count[0]);
  EXPECT_NE(changed[1], count[1]);
  EXPECT_NE(changed[2], count[2]);
  EXPECT_EQ(changed[3], count[3]);
  const int node0 = changed[0] + changed[3], node1 = changed[0] + changed[1], node2 = changed[1] + changed[2];
  EXPECT_EQ(node0 % 2, 0);
  EXPECT_EQ(node1 % 2, 0);
  EXPECT_EQ(node2 % 2, 0);
}

TEST(ParityPairing, AnOddNodeWithNoWayOutIsReported) {
  // Two nodes joined by one unit, one of them odd, no unit of anyone's own: the sum
  // of totals is odd, and no change can make both even.
  const std::vector<ParityUnit> units{{{0}, {0, 1}}};
  std::vector<int> count{3};
  EXPECT_EQ(make_nodes_even({1, 0}, units, {3.0}, {1}, count), 0);
}

}  // namespace
}  // namespace tquad
