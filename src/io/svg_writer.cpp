#include "io/svg_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "io/atomic_file_writer.h"

namespace tquad {

namespace {

constexpr double margin = 12;       // px around the drawing inside a panel
constexpr double font_size = 12;    // px
constexpr double line_height = 15;  // px per caption line

struct Point2 {
  double x, y;
};

// Orthonormal u, v with u x v = n, so the view from the normal's tip keeps
// orientation; n = z gives u = x, v = y exactly.
void plane_basis(const Vec3& normal, Vec3& u, Vec3& v) {
  const double length = norm(normal);
  if (!(length > 0) || !std::isfinite(length)) throw std::invalid_argument("SVG view normal is zero");
  const Vec3 n = (1.0 / length) * normal;
  const Vec3 helper = std::abs(n.y) < 0.9 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
  u = cross(helper, n);
  u = (1.0 / norm(u)) * u;
  v = cross(n, u);
}

std::string escape_xml(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// Splits at '\n', then wraps each line to at most `width` characters, breaking after
// a space or a comma when there is one (template trees have no spaces).
std::vector<std::string> wrap_caption(const std::string& caption, std::size_t width) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= caption.size()) {
    const std::size_t end = std::min(caption.find('\n', start), caption.size());
    std::string line = caption.substr(start, end - start);
    while (line.size() > width) {
      std::size_t cut = line.find_last_of(" ,", width - 1);
      cut = (cut == std::string::npos || cut == 0) ? width : cut + 1;
      std::string head = line.substr(0, cut);
      while (!head.empty() && head.back() == ' ') head.pop_back();
      lines.push_back(head);
      line = line.substr(cut);
    }
    lines.push_back(line);
    start = end + 1;
  }
  if (!lines.empty() && lines.back().empty() && caption.empty()) lines.pop_back();
  return lines;
}

std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", value);
  return buffer;
}

class PanelDrawer {
 public:
  PanelDrawer(const SvgPanel& panel, const Vec3& u, const Vec3& v, double left, double top, double size)
      : panel_(panel) {
    const QuadMesh& mesh = *panel.mesh;
    projected_.reserve(mesh.nodes.size());
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (const Vec3& p : mesh.nodes) {
      const Point2 q{dot(p, u), dot(p, v)};
      projected_.push_back(q);
      xmin = std::min(xmin, q.x); xmax = std::max(xmax, q.x);
      ymin = std::min(ymin, q.y); ymax = std::max(ymax, q.y);
    }
    const double extent = std::max(xmax - xmin, ymax - ymin);
    scale_ = extent > 0 ? (size - 2 * margin) / extent : 1.0;
    // Centre the drawing in the panel; SVG y grows downwards.
    offset_x_ = left + size / 2 - scale_ * (xmin + xmax) / 2;
    offset_y_ = top + size / 2 + scale_ * (ymin + ymax) / 2;
  }

  void draw(std::ostream& out) const {
    const QuadMesh& mesh = *panel_.mesh;
    // Each interior edge belongs to two quads: draw it once.
    std::vector<std::pair<NodeId, NodeId>> edges;
    edges.reserve(mesh.quads.size() * 4);
    for (const Quad& q : mesh.quads) {
      for (int i = 0; i < 4; ++i) edges.emplace_back(std::minmax(q[i], q[(i + 1) % 4]));
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    // Streamed in chunks: a large mesh's path data would be a huge string.
    out << "<path d=\"";
    std::string chunk;
    for (const auto& [a, b] : edges) {
      chunk += "M" + at(a) + "L" + at(b);
      if (chunk.size() > (1u << 16)) { out << chunk; chunk.clear(); }
    }
    out << chunk << "\" fill=\"none\" stroke=\"#555\" stroke-width=\"0.6\"/>\n";

    std::string cuts;
    for (const auto& cut : mesh.subregion_cuts) {
      for (std::size_t i = 0; i < cut.size(); ++i) cuts += (i == 0 ? "M" : "L") + at(cut[i]);
    }
    if (!cuts.empty()) {
      out << "<path d=\"" << cuts << "\" fill=\"none\" stroke=\"#000\" stroke-width=\"2.2\" "
          << "stroke-linejoin=\"round\" stroke-linecap=\"round\"/>\n";
    }
    const int n = std::min<int>(panel_.boundary_points, static_cast<int>(mesh.nodes.size()));
    if (n > 0) {
      std::string loop;
      for (int i = 0; i < n; ++i) loop += (i == 0 ? "M" : "L") + at(i);
      out << "<path d=\"" << loop << "Z\" fill=\"none\" stroke=\"#000\" stroke-width=\"2.2\" "
          << "stroke-linejoin=\"round\"/>\n";
    }
    for (int corner : mesh.corners_used) {
      if (corner < 0 || corner >= static_cast<int>(projected_.size())) continue;
      const Point2 p = screen(corner);
      out << "<circle cx=\"" << number(p.x) << "\" cy=\"" << number(p.y) << "\" r=\"3.5\" fill=\"#000\"/>\n";
    }
  }

 private:
  Point2 screen(NodeId id) const {
    const Point2& q = projected_[static_cast<std::size_t>(id)];
    return {offset_x_ + scale_ * q.x, offset_y_ - scale_ * q.y};
  }
  std::string at(NodeId id) const {
    const Point2 p = screen(id);
    return number(p.x) + " " + number(p.y);
  }

  const SvgPanel& panel_;
  std::vector<Point2> projected_;
  double scale_ = 1, offset_x_ = 0, offset_y_ = 0;
};

}  // namespace

void write_svg(std::ostream& out, const std::vector<SvgPanel>& panels, const SvgOptions& options) {
  const int count = static_cast<int>(panels.size());
  const int columns = std::max(1, std::min(options.columns, std::max(count, 1)));
  const int rows = (count + columns - 1) / columns;
  const double size = options.panel_size;
  // How many monospace characters (about 0.6 em wide) fit in a panel's width.
  const auto chars = static_cast<std::size_t>(std::max(8.0, (size - margin) / (0.62 * font_size)));

  std::vector<std::vector<std::string>> captions;
  std::size_t caption_lines = 0;
  for (const SvgPanel& panel : panels) {
    captions.push_back(wrap_caption(panel.caption, chars));
    caption_lines = std::max(caption_lines, captions.back().size());
  }
  const double caption_height = caption_lines > 0 ? line_height * caption_lines + 6 : 0;
  const double cell_height = size + caption_height;
  const double width = columns * size, height = std::max(rows, 1) * cell_height;

  Vec3 u{1, 0, 0}, v{0, 1, 0};
  if (options.view_normal) plane_basis(*options.view_normal, u, v);

  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << number(width) << "\" height=\""
      << number(height) << "\" viewBox=\"0 0 " << number(width) << " " << number(height) << "\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
  for (int i = 0; i < count; ++i) {
    const double left = (i % columns) * size, top = (i / columns) * cell_height;
    out << "<g>\n";
    if (panels[i].mesh != nullptr && !panels[i].mesh->nodes.empty()) {
      PanelDrawer(panels[i], u, v, left, top, size).draw(out);
    }
    for (std::size_t line = 0; line < captions[i].size(); ++line) {
      out << "<text x=\"" << number(left + size / 2) << "\" y=\""
          << number(top + size + line_height * (line + 1)) << "\" font-family=\"DejaVu Sans Mono, monospace\" "
          << "font-size=\"" << font_size << "\" text-anchor=\"middle\">" << escape_xml(captions[i][line])
          << "</text>\n";
    }
    out << "</g>\n";
  }
  out << "</svg>\n";
}

void write_svg_file(const std::string& path, const std::vector<SvgPanel>& panels, const SvgOptions& options) {
  write_file_atomically(path, [&](std::ostream& out) { write_svg(out, panels, options); });
}

}  // namespace tquad
