// make_bracket: the exact CAD reference of the paper's experiment (section 3). Builds a die-cast
// bracket of 90x25x12 mm as an OpenCASCADE solid (or reads a STEP file), tessellates it, and writes
//   <out>/reference.ply   the closed triangle mesh, per-face quality = B-rep face index;
//   <out>/reference.json  per B-rep face: index, surface type, exact parameters in the conventions of
//                         common/base/primitive.h, area and triangle count.
// Because every triangle comes from one B-rep face, the reference's segmentation and primitive types
// are exact, which is what the segmentation and fitting benchmarks score against.
//
// Usage: make_bracket [--step FILE] [--out DIR] [--deflection MM] [--angle RAD]
#include "bracket_mesh.h"
#include "bench/read_number.h"

#include "common/geometry/closest_point_on_primitive.h"
#include "common/base/primitive.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/stat.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBndLib.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepFilletAPI_MakeChamfer.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepGProp.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepTools.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>
#include <gp_Cone.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Pln.hxx>
#include <gp_Sphere.hxx>
#include <gp_Torus.hxx>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

// ---- Building the bracket ------------------------------------------------------------------------
// Dimensions in mm. The plate lies on z = 0; the boss rises to the part's full 12 mm height.
constexpr double kLength = 90, kWidth = 25, kPlate = 5, kHeight = 12;
constexpr double kCorner = 5;        // vertical corner rounds (cylinders)
constexpr double kTopRound = 1.5;    // plate top edge fillet (cylinders along lines, tori at corners)
constexpr double kBottomChamfer = 0.8; // plate bottom edge chamfer (planes, cones at the corners)
constexpr double kBossX = 45, kBossY = 12.5, kBossBase = 9, kBossTop = 8; // drafted boss (cone)
constexpr double kBossFoot = 2, kBossRim = 1; // fillets at the boss foot and rim (tori)
constexpr double kBossHole = 4, kBossHoleChamfer = 0.8;
constexpr double kHoleR = 2.75;      // M5 clearance holes
constexpr double kCsinkX = 10, kCsinkR = 5; // countersunk hole, 90 degree countersink, diameter 10
constexpr double kPlainX = 80;
constexpr double kSlotX0 = 62, kSlotX1 = 70, kSlotR = 2.5; // obround slot (planes + half cylinders)
constexpr double kDimpleX = 27, kDimpleR = 4, kDimpleDepth = 1.5; // spherical dimple

bool near(double a, double b) { return std::abs(a - b) < 1e-6; }

// Edges of `shape` accepted by `keep`.
std::vector<TopoDS_Edge> select_edges(const TopoDS_Shape& shape, const std::function<bool(const TopoDS_Edge&)>& keep)
{
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  std::vector<TopoDS_Edge> out;
  for (int i = 1; i <= edges.Extent(); ++i) {
    const TopoDS_Edge& e = TopoDS::Edge(edges(i));
    if (keep(e))
      out.push_back(e);
  }
  return out;
}

// True when both end points (or, for closed edges, a point) of the edge lie at height z.
bool edge_at_height(const TopoDS_Edge& e, double z)
{
  BRepAdaptor_Curve c(e);
  return near(c.Value(c.FirstParameter()).Z(), z) && near(c.Value(c.LastParameter()).Z(), z) &&
         near(c.Value(0.5 * (c.FirstParameter() + c.LastParameter())).Z(), z);
}

bool edge_is_vertical_line(const TopoDS_Edge& e)
{
  BRepAdaptor_Curve c(e);
  return c.GetType() == GeomAbs_Line && std::abs(std::abs(c.Line().Direction().Z()) - 1) < 1e-9;
}

// A circle edge centred on the vertical axis through (x, y), at height z.
bool edge_is_circle_at(const TopoDS_Edge& e, double x, double y, double z)
{
  BRepAdaptor_Curve c(e);
  if (c.GetType() != GeomAbs_Circle)
    return false;
  const gp_Pnt o = c.Circle().Location();
  return near(o.X(), x) && near(o.Y(), y) && near(o.Z(), z);
}

// The outer boundary edges of the plate at height z: not circles around a hole or the boss.
bool edge_on_plate_outline(const TopoDS_Edge& e, double z)
{
  if (!edge_at_height(e, z))
    return false;
  BRepAdaptor_Curve c(e);
  const gp_Pnt p = c.Value(0.5 * (c.FirstParameter() + c.LastParameter()));
  return p.X() < 1e-6 + kCorner || p.X() > kLength - kCorner - 1e-6 || p.Y() < 1e-6 + kCorner ||
         p.Y() > kWidth - kCorner - 1e-6;
}

TopoDS_Shape fillet(const TopoDS_Shape& s, const std::vector<TopoDS_Edge>& edges, double r, const char* what)
{
  BRepFilletAPI_MakeFillet mk(s);
  for (const TopoDS_Edge& e : edges)
    mk.Add(r, e);
  mk.Build();
  if (!mk.IsDone() || edges.empty())
    throw std::runtime_error(std::string("fillet failed: ") + what);
  return mk.Shape();
}

TopoDS_Shape chamfer(const TopoDS_Shape& s, const std::vector<TopoDS_Edge>& edges, double d, const char* what)
{
  BRepFilletAPI_MakeChamfer mk(s);
  for (const TopoDS_Edge& e : edges)
    mk.Add(d, e);
  mk.Build();
  if (!mk.IsDone() || edges.empty())
    throw std::runtime_error(std::string("chamfer failed: ") + what);
  return mk.Shape();
}

TopoDS_Shape cut(const TopoDS_Shape& a, const TopoDS_Shape& b, const char* what)
{
  BRepAlgoAPI_Cut op(a, b);
  if (!op.IsDone())
    throw std::runtime_error(std::string("cut failed: ") + what);
  return op.Shape();
}

gp_Ax2 vertical_axis(double x, double y, double z) { return gp_Ax2(gp_Pnt(x, y, z), gp_Dir(0, 0, 1)); }

// A die-cast mounting bracket: a plate with rounded corners, filleted top and chamfered bottom edges,
// a drafted boss with a chamfered bore, filleted at its foot and rim, a countersunk hole, a plain
// hole, an obround slot and a spherical dimple (a locating mark).
TopoDS_Shape build_bracket()
{
  TopoDS_Shape s = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(kLength, kWidth, kPlate)).Shape();
  s = fillet(s, select_edges(s, edge_is_vertical_line), kCorner, "plate corners");
  s = fillet(s, select_edges(s, [](const TopoDS_Edge& e) { return edge_on_plate_outline(e, kPlate); }),
             kTopRound, "plate top edges");
  s = chamfer(s, select_edges(s, [](const TopoDS_Edge& e) { return edge_on_plate_outline(e, 0); }),
              kBottomChamfer, "plate bottom edges");

  // The boss starts 1 mm below the plate top so the fuse has no coplanar faces.
  const double boss_r0 = kBossBase - (kBossBase - kBossTop) * (kPlate - 1) / kHeight;
  TopoDS_Shape boss =
      BRepPrimAPI_MakeCone(vertical_axis(kBossX, kBossY, kPlate - 1), boss_r0, kBossTop, kHeight - kPlate + 1).Shape();
  BRepAlgoAPI_Fuse fuse(s, boss);
  if (!fuse.IsDone())
    throw std::runtime_error("fuse failed: boss");
  s = fuse.Shape();
  s = fillet(s, select_edges(s, [](const TopoDS_Edge& e) { return edge_is_circle_at(e, kBossX, kBossY, kPlate); }),
             kBossFoot, "boss foot");
  s = fillet(s, select_edges(s, [](const TopoDS_Edge& e) { return edge_is_circle_at(e, kBossX, kBossY, kHeight); }),
             kBossRim, "boss rim");

  // Bore through the boss with a 45 degree chamfer at the top (a cone).
  s = cut(s, BRepPrimAPI_MakeCylinder(vertical_axis(kBossX, kBossY, -1), kBossHole, kHeight + 2).Shape(), "bore");
  s = cut(s, BRepPrimAPI_MakeCone(vertical_axis(kBossX, kBossY, kHeight - kBossHoleChamfer), kBossHole,
                                  kBossHole + kBossHoleChamfer + 1, kBossHoleChamfer + 1).Shape(), "bore chamfer");

  // Countersunk hole: 90 degree cone from the plate top, then the clearance hole.
  s = cut(s, BRepPrimAPI_MakeCone(vertical_axis(kCsinkX, kBossY, kPlate - kCsinkR), 0, kCsinkR + 1, kCsinkR + 1).Shape(),
          "countersink");
  s = cut(s, BRepPrimAPI_MakeCylinder(vertical_axis(kCsinkX, kBossY, -1), kHoleR, kPlate + 2).Shape(), "countersunk hole");
  s = cut(s, BRepPrimAPI_MakeCylinder(vertical_axis(kPlainX, kBossY, -1), kHoleR, kPlate + 2).Shape(), "plain hole");

  // Obround slot: two end cylinders and the box between them.
  TopoDS_Shape slot = BRepPrimAPI_MakeBox(gp_Pnt(kSlotX0, kBossY - kSlotR, -1), gp_Pnt(kSlotX1, kBossY + kSlotR, kPlate + 1)).Shape();
  for (double x : {kSlotX0, kSlotX1}) {
    BRepAlgoAPI_Fuse f(slot, BRepPrimAPI_MakeCylinder(vertical_axis(x, kBossY, -1), kSlotR, kPlate + 2).Shape());
    if (!f.IsDone())
      throw std::runtime_error("fuse failed: slot");
    slot = f.Shape();
  }
  s = cut(s, slot, "slot");

  // Spherical dimple, 1.5 mm deep.
  s = cut(s, BRepPrimAPI_MakeSphere(gp_Pnt(kDimpleX, kBossY, kPlate + kDimpleR - kDimpleDepth), kDimpleR).Shape(), "dimple");
  return s;
}

TopoDS_Shape read_step(const std::string& path)
{
  STEPControl_Reader reader;
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
    throw std::runtime_error(path + ": cannot read STEP file");
  if (reader.TransferRoots() == 0)
    throw std::runtime_error(path + ": no shape in STEP file");
  return reader.OneShape();
}

// ---- Describing the faces ---------------------------------------------------------------------------

std::string vec(const gp_XYZ& v)
{
  char buf[128];
  // + 0.0 turns -0 into 0.
  std::snprintf(buf, sizeof buf, "[%.9g, %.9g, %.9g]", v.X() + 0.0, v.Y() + 0.0, v.Z() + 0.0);
  return buf;
}

std::string num(double v)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

// A B-rep face's analytic surface in the conventions of common/base/primitive.h, and on which side the
// material is: outward = +1 when the outward normal points away from the axis/centre (a boss, a ball),
// -1 when towards it (a hole, a dimple, a concave fillet); planes carry their outward normal. The
// outward normal is sampled on the face (BRepGProp_Face honours the face orientation), so surfaces with
// left-handed frames need no special case.
struct FaceSurface
{
  bool analytic = false;
  primitive_edit::Primitive prim;
  double outward = 1;
};

Eigen::Vector3d eig(const gp_XYZ& v) { return Eigen::Vector3d(v.X(), v.Y(), v.Z()); }

FaceSurface face_surface(const TopoDS_Face& face)
{
  using primitive_edit::PrimitiveType;
  BRepAdaptor_Surface s(face, true);
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  gp_Pnt pnt;
  gp_Vec nrm;
  BRepGProp_Face(face).Normal(0.5 * (u0 + u1), 0.5 * (v0 + v1), pnt, nrm);
  const gp_XYZ p = pnt.XYZ();
  const gp_XYZ n = nrm.Magnitude() > 0 ? nrm.Normalized().XYZ() : gp_XYZ(0, 0, 0);
  FaceSurface f;
  f.analytic = true;
  gp_XYZ centre; // the point the outward normal is compared with
  switch (s.GetType()) {
  case GeomAbs_Plane:
    f.prim.type = PrimitiveType::Plane;
    f.prim.origin = eig(s.Plane().Location().XYZ());
    f.prim.axis = eig(n);
    return f;
  case GeomAbs_Cylinder: {
    const gp_Cylinder c = s.Cylinder();
    const gp_XYZ a = c.Axis().Direction().XYZ(), o = c.Location().XYZ();
    f.prim.type = PrimitiveType::Cylinder;
    f.prim.origin = eig(o);
    f.prim.axis = eig(a);
    f.prim.radius = c.Radius();
    centre = o + a * a.Dot(p - o);
    break;
  }
  case GeomAbs_Cone: {
    const gp_Cone c = s.Cone();
    const gp_XYZ a = c.Axis().Direction().XYZ(), apex = c.Apex().XYZ();
    f.prim.type = PrimitiveType::Cone;
    f.prim.origin = eig(apex);
    // The radius grows along OCCT's axis direction when the semi-angle is positive.
    f.prim.axis = eig(c.SemiAngle() < 0 ? a.Reversed() : a);
    f.prim.half_angle = std::abs(c.SemiAngle());
    centre = apex + a * a.Dot(p - apex);
    break;
  }
  case GeomAbs_Sphere:
    f.prim.type = PrimitiveType::Sphere;
    f.prim.origin = eig(s.Sphere().Location().XYZ());
    f.prim.radius = s.Sphere().Radius();
    centre = s.Sphere().Location().XYZ();
    break;
  case GeomAbs_Torus: {
    const gp_Torus c = s.Torus();
    const gp_XYZ a = c.Axis().Direction().XYZ(), o = c.Location().XYZ();
    f.prim.type = PrimitiveType::Torus;
    f.prim.origin = eig(o);
    f.prim.axis = eig(a);
    f.prim.radius = c.MajorRadius();
    f.prim.minor_radius = c.MinorRadius();
    gp_XYZ radial = (p - o) - a * a.Dot(p - o);
    if (radial.Modulus() > 0)
      radial.Normalize();
    centre = o + radial * c.MajorRadius(); // the tube centre nearest to p
    break;
  }
  default: f.analytic = false; return f;
  }
  f.outward = n.Dot(p - centre) >= 0 ? 1.0 : -1.0;
  return f;
}

std::string vec(const Eigen::Vector3d& v) { return vec(gp_XYZ(v.x(), v.y(), v.z())); }

// The surface as JSON members, with the parameter names of reference.json (see README.md).
std::string surface_json(const FaceSurface& f)
{
  using primitive_edit::PrimitiveType;
  const primitive_edit::Primitive& q = f.prim;
  std::ostringstream o;
  if (!f.analytic)
    return "\"type\": \"other\"";
  switch (q.type) {
  case PrimitiveType::Plane: o << "\"type\": \"plane\", \"point\": " << vec(q.origin) << ", \"normal\": " << vec(q.axis); break;
  case PrimitiveType::Cylinder:
    o << "\"type\": \"cylinder\", \"point\": " << vec(q.origin) << ", \"axis\": " << vec(q.axis)
      << ", \"radius\": " << num(q.radius);
    break;
  case PrimitiveType::Cone:
    o << "\"type\": \"cone\", \"apex\": " << vec(q.origin) << ", \"axis\": " << vec(q.axis)
      << ", \"half_angle\": " << num(q.half_angle);
    break;
  case PrimitiveType::Sphere:
    o << "\"type\": \"sphere\", \"centre\": " << vec(q.origin) << ", \"radius\": " << num(q.radius);
    break;
  case PrimitiveType::Torus:
    o << "\"type\": \"torus\", \"centre\": " << vec(q.origin) << ", \"axis\": " << vec(q.axis)
      << ", \"major_radius\": " << num(q.radius) << ", \"minor_radius\": " << num(q.minor_radius);
    break;
  }
  if (q.type != PrimitiveType::Plane)
    o << ", \"outward\": " << num(f.outward);
  return o.str();
}

double face_area(const TopoDS_Face& face)
{
  GProp_GProps props;
  BRepGProp::SurfaceProperties(face, props);
  return props.Mass();
}

// ---- Tessellation -----------------------------------------------------------------------------------

struct Tessellation
{
  std::vector<gp_XYZ> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> face_of_triangle;
  std::vector<int> triangles_per_face;
};

// Triangles of every face, outward, with the nodes shared along edges merged: BRepMesh puts the same
// 3D edge nodes into the triangulations of both faces of an edge, so equal coordinates are the same node.
Tessellation tessellate(const TopTools_IndexedMapOfShape& faces)
{
  Tessellation t;
  std::map<std::array<double, 3>, int> node_index;
  for (int fi = 1; fi <= faces.Extent(); ++fi) {
    const TopoDS_Face& face = TopoDS::Face(faces(fi));
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
    int count = 0;
    if (!tri.IsNull()) {
      std::vector<int> ids(tri->NbNodes() + 1);
      for (int n = 1; n <= tri->NbNodes(); ++n) {
        const gp_Pnt p = tri->Node(n).Transformed(loc.Transformation());
        const auto key = std::array<double, 3>{p.X(), p.Y(), p.Z()};
        const auto it = node_index.emplace(key, static_cast<int>(t.points.size()));
        if (it.second)
          t.points.push_back(p.XYZ());
        ids[n] = it.first->second;
      }
      const bool reversed = face.Orientation() == TopAbs_REVERSED;
      for (int k = 1; k <= tri->NbTriangles(); ++k) {
        int a, b, c;
        tri->Triangle(k).Get(a, b, c);
        if (reversed)
          std::swap(b, c);
        // A sphere's pole is one node per triangle fan in BRepMesh: merged, its triangles collapse.
        if (ids[a] == ids[b] || ids[b] == ids[c] || ids[c] == ids[a])
          continue;
        t.triangles.push_back({ids[a], ids[b], ids[c]});
        t.face_of_triangle.push_back(fi - 1);
        ++count;
      }
    }
    t.triangles_per_face.push_back(count);
  }
  return t;
}

// Checks the exported parameters against the tessellation with common/geometry/closest_point_on_primitive.h:
// every node of a face must lie on its primitive, every triangle must face the side "outward" says.
// Returns the largest node distance; counts the triangles facing the other way.
double check_surfaces(const std::vector<FaceSurface>& surfaces, const Tessellation& t, int* misoriented)
{
  double worst = 0;
  *misoriented = 0;
  for (size_t k = 0; k < t.triangles.size(); ++k) {
    const FaceSurface& f = surfaces[t.face_of_triangle[k]];
    if (!f.analytic)
      continue;
    Eigen::Vector3d v[3];
    for (int j = 0; j < 3; ++j) {
      v[j] = eig(t.points[t.triangles[k][j]]);
      worst = std::max(worst, std::abs(primitive_edit::project_onto_primitive(f.prim, v[j]).signed_distance));
    }
    const Eigen::Vector3d normal = (v[1] - v[0]).cross(v[2] - v[0]);
    const Eigen::Vector3d surface_normal = primitive_edit::project_onto_primitive(f.prim, (v[0] + v[1] + v[2]) / 3).normal;
    const double expected = f.prim.type == primitive_edit::PrimitiveType::Plane ? 1.0 : f.outward;
    if (normal.dot(surface_normal) * expected < 0)
      ++*misoriented;
  }
  return worst;
}

bool write_json(const std::string& path, const std::string& source, const TopTools_IndexedMapOfShape& faces,
                const std::vector<FaceSurface>& surfaces, const Tessellation& t, const Bnd_Box& box, double deflection)
{
  std::ofstream out(path);
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  out << "{\n  \"source\": \"" << source << "\",\n  \"units\": \"mm\",\n  \"deflection\": " << num(deflection)
      << ",\n  \"bbox_min\": " << vec(gp_XYZ(x0, y0, z0)) << ",\n  \"bbox_max\": " << vec(gp_XYZ(x1, y1, z1))
      << ",\n  \"vertices\": " << t.points.size() << ",\n  \"triangles\": " << t.triangles.size() << ",\n  \"faces\": [\n";
  // "surface": the first face on the same analytic surface (a boolean can split one cylinder into two
  // faces); a segmentation that keeps them together is right.
  std::map<std::string, int> first_on_surface;
  for (int fi = 1; fi <= faces.Extent(); ++fi) {
    const TopoDS_Face& face = TopoDS::Face(faces(fi));
    const std::string surface = surface_json(surfaces[fi - 1]);
    const int same = first_on_surface.emplace(surface, fi - 1).first->second;
    out << "    {\"index\": " << fi - 1 << ", \"surface\": " << same << ", " << surface
        << ", \"area\": " << num(face_area(face)) << ", \"triangles\": " << t.triangles_per_face[fi - 1] << "}"
        << (fi < faces.Extent() ? ",\n" : "\n");
  }
  out << "  ]\n}\n";
  return static_cast<bool>(out);
}

bool write_ply(const std::string& path, const Tessellation& t, std::string* message)
{
  bracket::BMesh m;
  auto vi = vcg::tri::Allocator<bracket::BMesh>::AddVertices(m, t.points.size());
  for (const gp_XYZ& p : t.points)
    (vi++)->P() = vcg::Point3d(p.X(), p.Y(), p.Z());
  auto fi = vcg::tri::Allocator<bracket::BMesh>::AddFaces(m, t.triangles.size());
  for (size_t k = 0; k < t.triangles.size(); ++k, ++fi) {
    for (int j = 0; j < 3; ++j)
      fi->V(j) = &m.vert[t.triangles[k][j]];
    fi->Q() = t.face_of_triangle[k];
  }
  // A closed, consistently oriented mesh is what the CT simulation's ray parity relies on.
  vcg::tri::UpdateTopology<bracket::BMesh>::FaceFace(m);
  const int nonmanifold = vcg::tri::Clean<bracket::BMesh>::CountNonManifoldEdgeFF(m);
  int border = 0;
  for (const auto& f : m.face)
    for (int j = 0; j < 3; ++j)
      border += vcg::face::IsBorder(f, j) ? 1 : 0;
  bool oriented = false, orientable = false;
  if (nonmanifold == 0)
    vcg::tri::Clean<bracket::BMesh>::OrientCoherentlyMesh(m, oriented, orientable);
  if (nonmanifold == 0 && border == 0 && oriented && vcg::tri::Stat<bracket::BMesh>::ComputeMeshVolume(m) <= 0) {
    *message = "tessellation is inside out (negative volume)";
    return false;
  }
  if (nonmanifold != 0 || border != 0 || !oriented) {
    *message = "tessellation is not a closed oriented surface (" + std::to_string(border) + " border edges, " +
               std::to_string(nonmanifold) + " non-manifold edges)";
    return false;
  }
  if (!bracket::save_ply(m, path, true)) {
    *message = path + ": cannot write";
    return false;
  }
  return true;
}

void usage()
{
  std::fprintf(stderr,
               "usage: make_bracket [--step FILE] [--out DIR] [--deflection MM] [--angle RAD]\n"
               "  builds the 90x25x12 mm die-cast bracket (or reads FILE), writes DIR/reference.ply\n"
               "  (per-face quality = B-rep face index) and DIR/reference.json (faces, types, parameters).\n"
               "  --deflection: tessellation chordal deviation, mm (default 0.005)\n"
               "  --angle: tessellation angular deviation, radians (default 0.1)\n");
}

} // namespace

int main(int argc, char** argv)
{
  std::string step, out_dir = ".";
  double deflection = 0.005, angle = 0.1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--step" && has_value)
      step = argv[++i];
    else if (a == "--out" && has_value)
      out_dir = argv[++i];
    else if (a == "--deflection" && has_value) {
      if (!read_number("--deflection", argv[++i], deflection))
        return 2;
    } else if (a == "--angle" && has_value) {
      if (!read_number("--angle", argv[++i], angle))
        return 2;
    } else {
      usage();
      return 2;
    }
  }
  if (!(deflection > 0) || !(angle > 0) || !std::isfinite(deflection) || !std::isfinite(angle)) {
    std::fprintf(stderr, "make_bracket: --deflection and --angle must be positive\n");
    return 2;
  }

  const auto t0 = std::chrono::steady_clock::now();
  try {
    const TopoDS_Shape shape = step.empty() ? build_bracket() : read_step(step);
    if (!BRepCheck_Analyzer(shape).IsValid())
      throw std::runtime_error("the solid is not valid (BRepCheck_Analyzer)");
    BRepMesh_IncrementalMesh mesher(shape, deflection, false, angle, true);
    if (!mesher.IsDone())
      throw std::runtime_error("tessellation failed");
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    const Tessellation t = tessellate(faces);
    std::vector<FaceSurface> surfaces;
    for (int fi = 1; fi <= faces.Extent(); ++fi)
      surfaces.push_back(face_surface(TopoDS::Face(faces(fi))));
    int misoriented = 0;
    const double deviation = check_surfaces(surfaces, t, &misoriented);
    if (deviation > deflection || misoriented > 0)
      throw std::runtime_error("the face parameters do not match the tessellation (node deviation " +
                               num(deviation) + " mm, " + std::to_string(misoriented) + " triangles facing inward)");
    Bnd_Box box;
    BRepBndLib::AddOptimal(shape, box, false, false);

    std::string message;
    if (!write_ply(out_dir + "/reference.ply", t, &message))
      throw std::runtime_error(message);
    if (!write_json(out_dir + "/reference.json", step.empty() ? "make_bracket" : step, faces, surfaces, t, box, deflection))
      throw std::runtime_error(out_dir + "/reference.json: cannot write");

    std::map<std::string, int> types;
    for (int fi = 1; fi <= faces.Extent(); ++fi) {
      static const char* names[] = {"plane", "cylinder", "cone", "sphere", "torus"};
      const GeomAbs_SurfaceType ty = BRepAdaptor_Surface(TopoDS::Face(faces(fi))).GetType();
      ++types[ty <= GeomAbs_Torus ? names[ty] : "other"];
    }
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("make_bracket: %d B-rep faces (", faces.Extent());
    for (const auto& kv : types)
      std::printf(" %s %d", kv.first.c_str(), kv.second);
    std::printf(" ), %zu vertices, %zu triangles, nodes within %.2g mm of their primitive, %.2f s\n",
                t.points.size(), t.triangles.size(), deviation, secs);
  } catch (const Standard_Failure& e) {
    std::fprintf(stderr, "make_bracket: OpenCASCADE error: %s\n", e.GetMessageString());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_bracket: %s\n", e.what());
    return 1;
  }
  return 0;
}
