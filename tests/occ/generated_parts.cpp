#include "generated_parts.h"

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepFilletAPI_MakeChamfer.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepTools.hxx>
#include <Bnd_Box.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax1.hxx>
#include <gp_Ax2.hxx>

#include <algorithm>
#include <functional>
#include <random>

#include <sys/wait.h>
#include <unistd.h>

namespace tquad {

namespace {

class Dice {
 public:
  explicit Dice(std::uint32_t seed) : engine_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }
  bool chance(double p) { return uniform(0, 1) < p; }

 private:
  std::mt19937 engine_;
};

struct Box {
  double x0, y0, z0, x1, y1, z1;
};

Box box_of(const TopoDS_Shape& shape) {
  Bnd_Box b;
  BRepBndLib::Add(shape, b);
  Box out;
  b.Get(out.x0, out.y0, out.z0, out.x1, out.y1, out.z1);
  return out;
}

// `step(shape)` when it succeeds with a valid, non-empty solid; else `shape` as it was.
TopoDS_Shape tried(const TopoDS_Shape& shape, const std::function<TopoDS_Shape(const TopoDS_Shape&)>& step) {
  try {
    const TopoDS_Shape next = step(shape);
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(next, TopAbs_FACE, faces);
    if (!next.IsNull() && faces.Extent() > 0 && BRepCheck_Analyzer(next).IsValid()) return next;
  } catch (const Standard_Failure&) {  // the step is skipped
  }
  return shape;
}

TopoDS_Shape unified(const TopoDS_Shape& shape) {
  ShapeUpgrade_UnifySameDomain unify(shape, true, true, false);
  unify.Build();
  return unify.Shape();
}

TopoDS_Shape base(Dice& dice) {
  const double length = dice.uniform(40, 120), width = dice.uniform(30, 90), height = dice.uniform(5, 30);
  switch (dice.integer(0, 3)) {
    case 2:
      return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(length / 2, width / 2, 0), gp_Dir(0, 0, 1)), width / 2, 2 * height)
          .Shape();
    case 3: {  // a turned profile: a shoulder and a taper
      BRepBuilderAPI_MakePolygon profile;
      for (const gp_Pnt& p : {gp_Pnt(0, 0, 0), gp_Pnt(width / 2, 0, 0), gp_Pnt(width / 2, 0, height),
                              gp_Pnt(width / 3, 0, height), gp_Pnt(width / 4, 0, 2 * height), gp_Pnt(0, 0, 2 * height)}) {
        profile.Add(p);
      }
      profile.Close();
      const TopoDS_Face face = BRepBuilderAPI_MakeFace(profile.Wire()).Face();
      return BRepPrimAPI_MakeRevol(face, gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1))).Shape();
    }
    default:
      return BRepPrimAPI_MakeBox(length, width, height).Shape();
  }
}

}  // namespace

TopoDS_Shape generated_part(std::uint32_t seed) {
  Dice dice(seed);
  TopoDS_Shape part = base(dice);
  const Box b = box_of(part);
  const double span = std::min(b.x1 - b.x0, b.y1 - b.y0), depth = b.z1 - b.z0;
  for (int holes = dice.integer(0, 5); holes > 0; --holes) {
    const double r = dice.uniform(1.5, span / 6);
    const double x = dice.uniform(b.x0 + r, b.x1 - r), y = dice.uniform(b.y0 + r, b.y1 - r);
    const double down = dice.chance(0.7) ? 2 * depth : dice.uniform(0.3, 0.8) * depth;
    part = tried(part, [&](const TopoDS_Shape& s) {
      return BRepAlgoAPI_Cut(s, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, b.z1 - down), gp_Dir(0, 0, 1)), r, down + 1)
                                    .Shape())
          .Shape();
    });
  }
  for (int bosses = dice.integer(0, 2); bosses > 0; --bosses) {
    const double r = dice.uniform(2, span / 5);
    const double x = dice.uniform(b.x0 + r, b.x1 - r), y = dice.uniform(b.y0 + r, b.y1 - r), h = dice.uniform(3, 15);
    part = tried(part, [&](const TopoDS_Shape& s) {
      return unified(
          BRepAlgoAPI_Fuse(s, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, b.z1 - 0.01), gp_Dir(0, 0, 1)), r, h).Shape())
              .Shape());
    });
  }
  if (dice.chance(0.5)) {  // a slot through
    const double w = dice.uniform(3, (b.y1 - b.y0) / 4), l = dice.uniform(2 * w, (b.x1 - b.x0) / 2);
    const double x = dice.uniform(b.x0, b.x1 - l), y = dice.uniform(b.y0, b.y1 - w);
    part = tried(part, [&](const TopoDS_Shape& s) {
      return BRepAlgoAPI_Cut(s, BRepPrimAPI_MakeBox(gp_Pnt(x, y, b.z0 - depth), l, w, 3 * depth).Shape()).Shape();
    });
  }
  if (dice.chance(0.3)) {  // a spherical dimple
    const gp_Pnt centre(dice.uniform(b.x0, b.x1), dice.uniform(b.y0, b.y1), b.z1);
    const double r = dice.uniform(3, 12);
    part = tried(part, [&](const TopoDS_Shape& s) {
      return BRepAlgoAPI_Cut(s, BRepPrimAPI_MakeSphere(centre, r).Shape()).Shape();
    });
  }
  const auto some_edges = [&](double share) {
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(part, TopAbs_EDGE, edges);
    std::vector<TopoDS_Edge> chosen;
    for (int i = 1; i <= edges.Extent(); ++i) {
      if (dice.chance(share)) chosen.push_back(TopoDS::Edge(edges(i)));
    }
    return chosen;
  };
  // Fillets, then chamfers, on a share of the edges: `add` puts one edge on the builder.
  const auto blend = [&](double p, double lo, double hi, double share, auto builder, auto add) {
    if (!dice.chance(p)) return;
    const double size = dice.uniform(lo, hi);
    const std::vector<TopoDS_Edge> edges = some_edges(share);
    part = tried(part, [&](const TopoDS_Shape& s) {
      auto maker = builder(s);
      for (const TopoDS_Edge& e : edges) add(maker, size, e);
      return maker.Shape();
    });
  };
  blend(0.6, 0.5, 4, 0.3, [](const TopoDS_Shape& s) { return BRepFilletAPI_MakeFillet(s); },
        [](BRepFilletAPI_MakeFillet& m, double r, const TopoDS_Edge& e) { m.Add(r, e); });
  blend(0.3, 0.5, 2, 0.2, [](const TopoDS_Shape& s) { return BRepFilletAPI_MakeChamfer(s); },
        [](BRepFilletAPI_MakeChamfer& m, double d, const TopoDS_Edge& e) { m.Add(d, e); });
  return part;
}

bool write_generated_part(std::uint32_t seed, const std::string& brep_path) {
  ::unlink(brep_path.c_str());
  const pid_t child = ::fork();
  if (child < 0) return false;
  if (child == 0) {
    const bool written = BRepTools::Write(generated_part(seed), brep_path.c_str());
    ::_exit(written ? 0 : 1);
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0) {
  }
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

TopoDS_Shape drilled_cone(double x, double y, double z) {
  const TopoDS_Shape cone = BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(x, y, z), gp_Dir(0, 0, 1)), 0.0, 5.0, 10.0).Shape();
  const TopoDS_Shape drill =
      BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x - 10, y, z + 6), gp_Dir(1, 0, 0)), 1.0, 20.0).Shape();
  return BRepAlgoAPI_Cut(cone, drill).Shape();
}

}  // namespace tquad
