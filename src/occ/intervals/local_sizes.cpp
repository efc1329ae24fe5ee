#include "occ/intervals/local_sizes.h"

#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <queue>

#include "core/input_error.h"
#include "occ/intervals/edge_discretization.h"

namespace tquad {

namespace {

constexpr double kMaxGrowthRate = 10.0;
const char* kind_name(LocalSize::Kind k) {
  switch (k) {
    case LocalSize::Kind::face: return "face";
    case LocalSize::Kind::edge: return "edge";
    case LocalSize::Kind::vertex: return "vertex";
  }
  return "?";
}

// Sizes grow linearly by ln(rate) per unit length: then segments cut at equal steps of
// the integral of dt / s(t) grow by the factor rate from one to the next (a linear
// size s = a + k t gives segments in the ratio e^k per unit step).
double slope(double rate) { return std::log(rate); }

// s(t) = min(own, first + k t, last + k (L - t)) in its three pieces: rising from the
// first vertex on [0, a], `own` on [a, b], falling to the last vertex on [b, L]; the
// integral F of dt / s(t) in closed form on each, and its inverse.
struct Profile {
  double k, own, first, last, length, a, b, fa, fb, total;

  Profile(const EdgeSizing& s, double length) : k(slope(s.rate)), own(s.own), first(s.first), last(s.last),
                                                length(length) {
    const double cross = std::clamp((last - first + k * length) / (2 * k), 0.0, length);
    a = std::min((own - first) / k, cross);
    b = std::max(length - (own - last) / k, cross);
    fa = std::log((first + k * a) / first) / k;
    fb = fa + (b - a) / own;
    total = fb + std::log((last + k * (length - b)) / last) / k;
  }
  // The arc length where F reaches g (0 <= g <= total).
  double at(double g) const {
    if (g <= fa) return first * std::expm1(k * g) / k;
    if (g <= fb) return a + (g - fa) * own;
    const double from_end = ((last + k * (length - b)) * std::exp(-k * (g - fb)) - last) / k;
    return std::clamp(length - from_end, b, length);
  }
};

}  // namespace

std::string local_size_name(const LocalSize& s) {
  return std::string(kind_name(s.kind)) + std::to_string(s.index);
}

LocalSize parse_local_size(const std::string& text) {
  const std::string what = "size entry '" + text + "'";
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos) {
    throw InputError(what + ": expected face<N>:<size>, edge<N>:<size> or vertex<N>:<size> (0-based N)");
  }
  const std::string entity = text.substr(0, colon), value = text.substr(colon + 1);
  LocalSize out;
  std::string digits;
  bool known = false;
  for (LocalSize::Kind k : {LocalSize::Kind::face, LocalSize::Kind::edge, LocalSize::Kind::vertex}) {
    const std::string name = kind_name(k);
    if (entity.compare(0, name.size(), name) == 0) {
      out.kind = k;
      digits = entity.substr(name.size());
      known = true;
    }
  }
  if (!known || digits.empty() || digits.size() > 9 ||
      !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    throw InputError(what + ": expected face<N>:<size>, edge<N>:<size> or vertex<N>:<size> (0-based N)");
  }
  out.index = std::stoi(digits);
  char* end = nullptr;
  out.size = value.empty() ? 0.0 : std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0' || !std::isfinite(out.size) || !(out.size > 0)) {
    throw InputError(what + ": the size must be a finite number over 0");
  }
  return out;
}

void check_growth_rate(double rate) {
  if (!(rate > 1.0 && rate <= kMaxGrowthRate)) {
    char text[96];
    std::snprintf(text, sizeof text, "the growth rate must be over 1 and at most %g, not %g", kMaxGrowthRate, rate);
    throw InputError(text);
  }
}

SizeField local_size_field(const ShapeIndex& index, double global, double min_size,
                           const std::vector<LocalSize>& sizes, double rate, const std::vector<double>& lengths) {
  check_growth_rate(rate);
  const int faces = index.face_count(), edges = index.edge_count(), vertices = index.vertex_count();
  const double inf = std::numeric_limits<double>::infinity();
  SizeField field;
  field.faces.assign(faces, global);
  std::vector<double> own(edges, global), at_vertex(vertices, inf);
  for (const LocalSize& s : sizes) {
    const int count = s.kind == LocalSize::Kind::face ? faces : s.kind == LocalSize::Kind::edge ? edges : vertices;
    if (s.index < 0 || s.index >= count) {
      throw InputError("size at " + local_size_name(s) + ": the shape has " + kind_name(s.kind) + "s 0.." +
                       std::to_string(count - 1));
    }
    if (!std::isfinite(s.size) || !(s.size > 0)) {
      throw InputError("size at " + local_size_name(s) + " must be a finite number over 0, not " +
                       std::to_string(s.size));
    }
    double& slot = s.kind == LocalSize::Kind::face   ? field.faces[s.index]
                   : s.kind == LocalSize::Kind::edge ? own[s.index]
                                                     : at_vertex[s.index];
    slot = std::min(slot, s.size);
  }
  const double floor = std::max(min_size, 0.0);
  for (int f = 0; f < faces; ++f) {
    field.faces[f] = std::max(field.faces[f], floor);
    for (TopExp_Explorer it(index.face(f), TopAbs_EDGE); it.More(); it.Next()) {
      const int e = index.edge_index(it.Current());
      if (e >= 0) own[e] = std::min(own[e], field.faces[f]);
    }
  }
  // Each edge's ends, and the vertices' sizes from the edges that meet there.
  std::vector<std::pair<int, int>> ends(edges, {-1, -1});
  for (int e = 0; e < edges; ++e) {
    own[e] = std::max(own[e], floor);
    if (!(lengths[e] > 0)) continue;
    TopoDS_Vertex first, last;
    TopExp::Vertices(forward(index.edge(e)), first, last);
    ends[e] = {index.vertex_index(first), index.vertex_index(last)};
    for (int v : {ends[e].first, ends[e].second}) {
      if (v >= 0) at_vertex[v] = std::min(at_vertex[v], own[e]);
    }
  }
  // Sizes grow by at most (rate - 1) per unit length away from any vertex: shortest
  // paths from the smallest sizes outward.
  std::vector<std::vector<std::pair<int, double>>> along(vertices);
  for (int e = 0; e < edges; ++e) {
    const auto [a, b] = ends[e];
    if (a < 0 || b < 0 || a == b) continue;
    along[a].push_back({b, lengths[e]});
    along[b].push_back({a, lengths[e]});
  }
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (int v = 0; v < vertices; ++v) {
    if (std::isfinite(at_vertex[v])) {
      at_vertex[v] = std::max(at_vertex[v], floor);
      queue.push({at_vertex[v], v});
    }
  }
  while (!queue.empty()) {
    const auto [h, v] = queue.top();
    queue.pop();
    if (h > at_vertex[v]) continue;
    for (const auto& [w, length] : along[v]) {
      const double reached = h + slope(rate) * length;
      if (reached < at_vertex[w]) {
        at_vertex[w] = reached;
        queue.push({reached, w});
      }
    }
  }
  field.edges.assign(edges, EdgeSizing{});
  field.smallest = global;
  for (int e = 0; e < edges; ++e) {
    EdgeSizing& s = field.edges[e];
    s.own = own[e];
    s.rate = rate;
    s.first = ends[e].first >= 0 ? std::min(own[e], at_vertex[ends[e].first]) : own[e];
    s.last = ends[e].second >= 0 ? std::min(own[e], at_vertex[ends[e].second]) : own[e];
    field.smallest = std::min({field.smallest, s.own, s.first, s.last});
  }
  return field;
}

double graded_segments(const EdgeSizing& sizing, double length) {
  if (!(length > 0)) return 0.0;
  if (!sizing.graded()) return length / sizing.own;
  return Profile(sizing, length).total;
}

std::vector<double> graded_positions(const EdgeSizing& sizing, double length, int n) {
  std::vector<double> out;
  if (n <= 1 || !(length > 0)) return out;
  if (!sizing.graded()) {
    for (int k = 1; k < n; ++k) out.push_back(length * k / n);
    return out;
  }
  const Profile profile(sizing, length);
  for (int k = 1; k < n; ++k) out.push_back(profile.at(profile.total * k / n));
  return out;
}

}  // namespace tquad
