// fuzz_input.h: what the libFuzzer targets share: a decoder of the input bytes into numbers, points of the
// five primitive shapes and meshes (with the special values that break geometry code: NaN, Inf, 1e6-scale,
// denormals, duplicates), and the invariant checks whose violation aborts (libFuzzer then saves the input).
#ifndef PRIMITIVE_EDIT_FUZZ_INPUT_H
#define PRIMITIVE_EDIT_FUZZ_INPUT_H

#include "common/base/constants.h"
#include "common/base/primitive.h"
#include "common/fit/fit_result.h"
#include "common/mesh/face_adjacency.h"

#include <vcg/complex/complex.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

namespace fuzz_mesh {

class FVertex;
class FFace;
struct FUsedTypes : public vcg::UsedTypes<vcg::Use<FVertex>::AsVertexType, vcg::Use<FFace>::AsFaceType> {};
class FVertex : public vcg::Vertex<FUsedTypes, vcg::vertex::Coord3d, vcg::vertex::Normal3d, vcg::vertex::BitFlags> {};
class FFace : public vcg::Face<FUsedTypes, vcg::face::VertexRef, vcg::face::Normal3d, vcg::face::BitFlags> {};
class FMesh : public vcg::tri::TriMesh<std::vector<FVertex>, std::vector<FFace>> {};

} // namespace fuzz_mesh

namespace fuzz {

using namespace primitive_edit;

[[noreturn]] inline void fail(const char* what, const char* file, int line)
{
  std::fprintf(stderr, "INVARIANT VIOLATED at %s:%d: %s\n", file, line, what);
  std::abort();
}
#define FUZZ_CHECK(cond)                                                                                              \
  do {                                                                                                                \
    if (!(cond))                                                                                                      \
      fuzz::fail(#cond, __FILE__, __LINE__);                                                                          \
  } while (0)

class Decoder
{
public:
  Decoder(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  uint8_t u8() { return pos_ < size_ ? data_[pos_++] : 0; }
  uint16_t u16() { return uint16_t(u8() | (uint16_t(u8()) << 8)); }
  uint32_t u32() { return uint32_t(u16()) | (uint32_t(u16()) << 16); }
  bool bit() { return (u8() & 1) != 0; }
  double unit() { return u16() / 65535.0; }               // [0, 1]
  double signed_unit() { return 2.0 * unit() - 1.0; }    // [-1, 1]
  // A number that is usually ordinary but sometimes one of the patterns that break geometry code.
  double special(double scale)
  {
    const uint8_t kind = u8();
    switch (kind % 24) {
    case 0: return std::numeric_limits<double>::quiet_NaN();
    case 1: return std::numeric_limits<double>::infinity();
    case 2: return -std::numeric_limits<double>::infinity();
    case 3: return 1e6 * signed_unit();
    case 4: return 1e-40 * signed_unit();   // a float denormal
    case 5: return 0.0;
    case 6: {
      const uint32_t bits = u32();
      float f;
      std::memcpy(&f, &bits, sizeof f);
      return double(f);
    }
    case 7: return 1e30 * signed_unit();
    default: return scale * signed_unit();
    }
  }
  size_t remaining() const { return pos_ < size_ ? size_ - pos_ : 0; }

private:
  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
};

inline Eigen::Vector3d unit_vector(Decoder& in)
{
  Eigen::Vector3d d(in.signed_unit(), in.signed_unit(), in.signed_unit());
  if (d.norm() < 1e-3)
    d = Eigen::Vector3d::UnitZ();
  return d.normalized();
}

// A primitive with fuzzed parameters: mostly valid, sometimes invalid (zero axis, negative radius, NaN).
inline Primitive fuzz_primitive(Decoder& in)
{
  Primitive p;
  p.type = static_cast<PrimitiveType>(in.u8() % kPrimitiveTypeCount);
  const bool wild = (in.u8() % 4) == 0;
  if (wild) {
    p.origin = Eigen::Vector3d(in.special(2), in.special(2), in.special(2));
    p.axis = Eigen::Vector3d(in.special(1), in.special(1), in.special(1));
    p.radius = in.special(2);
    p.minor_radius = in.special(1);
    p.half_angle = in.special(2);
  } else {
    p.origin = Eigen::Vector3d(in.signed_unit(), in.signed_unit(), in.signed_unit()) * 2.0;
    p.axis = unit_vector(in);
    p.radius = 0.05 + 3.0 * in.unit();
    p.minor_radius = 0.02 + p.radius * 1.2 * in.unit();
    p.half_angle = 0.001 + 1.5687 * in.unit();
  }
  return p;
}

// A point of the given shape at surface parameters (u, v) in [0, 1]^2 (shape 0: raw fuzzed coordinates).
inline Eigen::Vector3d shape_point(int shape, double u, double v, const Primitive& p)
{
  const double pi = kPi;
  const Eigen::Vector3d a = p.axis;
  const Eigen::Vector3d e1 = any_orthogonal(a);
  const Eigen::Vector3d e2 = a.cross(e1);
  const double t = 2 * pi * u;
  switch (shape) {
  case 1: return p.origin + 3 * (u - 0.5) * e1 + 3 * (v - 0.5) * e2;
  case 2: {
    const double phi = pi * (0.05 + 0.9 * v);
    return p.origin + p.radius * (std::sin(phi) * (std::cos(t) * e1 + std::sin(t) * e2) + std::cos(phi) * a);
  }
  case 3: return p.origin + p.radius * (std::cos(t) * e1 + std::sin(t) * e2) + 2 * (v - 0.5) * a;
  case 4: {
    const double h = 0.1 + 2 * v;
    return p.origin + h * a + h * std::tan(p.half_angle) * (std::cos(t) * e1 + std::sin(t) * e2);
  }
  default: {
    const double s = 2 * pi * v;
    const Eigen::Vector3d radial = std::cos(t) * e1 + std::sin(t) * e2;
    return p.origin + (p.radius + p.minor_radius * std::cos(s)) * radial + p.minor_radius * std::sin(s) * a;
  }
  }
}

// The primitive the decoded shape lies on: p when valid, else a unit one of p's type.
inline Primitive clean_primitive(const Primitive& p)
{
  if (primitive_is_valid(p))
    return p;
  Primitive clean = p;
  clean.origin.setZero();
  clean.axis = Eigen::Vector3d::UnitZ();
  clean.radius = 1;
  clean.minor_radius = 0.4;
  clean.half_angle = 0.5;
  return clean;
}

// Up to max_points points of a decoded patch of `surface` (shape 1 plane .. 5 torus as in shape_point, 0: raw
// fuzzed coordinates), spread by a low-discrepancy sequence, with noise and special values mixed in.
inline Eigen::MatrixX3d points_on(Decoder& in, int shape, const Primitive& surface, int max_points)
{
  const double u_span = 0.02 + in.unit(), v_span = 0.02 + in.unit();
  const double noise = in.unit() * in.unit() * 0.05;
  const int n = int(in.u16() % (max_points + 1));
  Eigen::MatrixX3d points(n, 3);
  for (int i = 0; i < n; ++i) {
    const double u = u_span * std::fmod(0.6180339887 * i, 1.0), v = v_span * std::fmod(0.7548776662 * i, 1.0);
    points.row(i) = shape == 0 ? Eigen::RowVector3d(in.special(1), in.special(1), in.special(1))
                               : shape_point(shape, u, v, surface).transpose();
  }
  for (int i = 0; i < n && noise > 0; ++i)
    points.row(i) += noise * Eigen::RowVector3d(std::sin(7.1 * i), std::sin(3.3 * i + 1), std::cos(5.7 * i));
  const int perturbations = in.u8() % 16;
  for (int k = 0; k < perturbations && n > 0; ++k) {
    const int i = in.u16() % n;
    switch (in.u8() % 3) {
    case 0: points(i, in.u8() % 3) = in.special(1); break;
    case 1: points.row(i) = points.row(in.u16() % n); break;
    default: points.row(i) += Eigen::RowVector3d(in.signed_unit(), in.signed_unit(), in.signed_unit());
    }
  }
  return points;
}

// Up to max_points points of a decoded shape at a decoded scale (1e-6 .. 1e6); `surface` is set to the
// primitive they lie on (for raw coordinates, a decoded one).
inline Eigen::MatrixX3d shape_points(Decoder& in, int max_points, Primitive& surface)
{
  const int shape = in.u8() % 6;
  surface = clean_primitive(fuzz_primitive(in));
  surface.type = shape == 0 ? surface.type : static_cast<PrimitiveType>(shape - 1);
  const double scale = std::pow(10.0, int(in.u8() % 13) - 6);
  Eigen::MatrixX3d points = points_on(in, shape, surface, max_points) * scale;
  surface.origin *= scale;
  surface.radius *= scale;
  surface.minor_radius *= scale;
  return points;
}

// Per-point weights: none (empty), ones, or decoded ones with special values (negative, NaN) mixed in.
inline Eigen::VectorXd decode_weights(Decoder& in, Eigen::Index n)
{
  switch (in.u8() % 3) {
  case 0: return {};
  case 1: return Eigen::VectorXd::Ones(n);
  default: {
    Eigen::VectorXd w(n);
    for (Eigen::Index i = 0; i < n; ++i)
      w[i] = in.remaining() > 0 ? in.special(1.0) : 1.0;
    return w;
  }
  }
}

// Frees a mesh's attributes (vcg::tri::Allocator's) with it: vcg's ~TriMesh does not (ClearAttributes is
// commented out there), and LeakSanitizer should report our leaks only.
template <class MeshType>
struct AttributeCleaner
{
  MeshType& mesh;
  ~AttributeCleaner() { mesh.ClearAttributes(); }
};

// How large a decoded mesh may get: a grid of at most max_side x max_side vertices of a shape (or up to
// max_vertices raw points), plus arbitrary faces up to max_faces.
struct MeshLimits
{
  int max_side = 31;
  int max_vertices = 1200;
  int max_faces = 2000;
};

template <class MeshType>
void build_mesh(Decoder& in, MeshType& m, const MeshLimits& limits = {})
{
  using Scalar = typename MeshType::ScalarType;
  const int shape = in.u8() % 6;
  const Primitive clean = clean_primitive(fuzz_primitive(in));
  const double scale = std::pow(10.0, int(in.u8() % 13) - 6);  // 1e-6 .. 1e6
  const double noise = in.unit() * in.unit() * 0.05;
  const int rows = 2 + in.u8() % (limits.max_side - 1);
  const int cols = 2 + in.u8() % (limits.max_side - 1);
  const double u_span = 0.02 + in.unit();  // a short arc of a cylinder, a cap of a sphere...
  const double v_span = 0.02 + in.unit();

  int nv = shape == 0 ? int(in.u16() % (limits.max_vertices + 1)) : std::min(rows * cols, limits.max_vertices);
  vcg::tri::Allocator<MeshType>::AddVertices(m, size_t(nv));
  for (int i = 0; i < nv; ++i) {
    Eigen::Vector3d p;
    if (shape == 0) {
      p = Eigen::Vector3d(in.special(1), in.special(1), in.special(1));
    } else {
      const int r = i / cols, c = i % cols;
      p = shape_point(shape, u_span * c / (cols - 1), v_span * r / std::max(rows - 1, 1), clean);
    }
    m.vert[size_t(i)].P() = typename MeshType::CoordType(Scalar(p.x() * scale), Scalar(p.y() * scale),
                                                         Scalar(p.z() * scale));
  }
  // Perturbations: noise, special values, duplicates of other vertices.
  const int perturbations = in.u8() % 32;
  for (int k = 0; k < perturbations && nv > 0; ++k) {
    const int i = in.u16() % nv;
    auto& P = m.vert[size_t(i)].P();
    switch (in.u8() % 4) {
    case 0: P[in.u8() % 3] = Scalar(in.special(1) * scale); break;
    case 1: P = m.vert[size_t(in.u16() % nv)].P(); break;
    default:
      for (int a = 0; a < 3; ++a)
        P[a] += Scalar(noise * scale * in.signed_unit());
    }
  }

  std::vector<std::array<int, 3>> faces;
  if (shape != 0 && nv == rows * cols) {
    const bool flip_some = in.bit();
    for (int r = 0; r + 1 < rows; ++r)
      for (int c = 0; c + 1 < cols; ++c) {
        const int a = r * cols + c, b = a + 1, d = a + cols, e = d + 1;
        std::array<int, 3> f1{a, b, e}, f2{a, e, d};
        if (flip_some && ((r * 7 + c) % 5 == 0))
          std::swap(f1[1], f1[2]);  // inconsistent orientation
        faces.push_back(f1);
        faces.push_back(f2);
      }
  }
  const int extra = nv > 0 ? int(in.u16() % (limits.max_faces + 1)) : 0;
  for (int k = 0; k < extra && int(faces.size()) < limits.max_faces && in.remaining() > 0; ++k)
    faces.push_back({int(in.u16() % nv), int(in.u16() % nv), int(in.u16() % nv)});
  if (int(faces.size()) > limits.max_faces)
    faces.resize(size_t(limits.max_faces));

  vcg::tri::Allocator<MeshType>::AddFaces(m, faces.size());
  for (size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k)
      m.face[f].V(k) = &m.vert[size_t(faces[f][size_t(k)])];
  // Deleted faces: vcg keeps them in the vector, flagged.
  const int deletions = in.u8() % 8;
  for (int k = 0; k < deletions && !faces.empty(); ++k) {
    auto& f = m.face[in.u16() % faces.size()];
    if (!f.IsD())
      vcg::tri::Allocator<MeshType>::DeleteFace(m, f);
  }
}


template <class MeshType>
void check_segmentation(const MeshType& m, const std::vector<int>& seg, int K)
{
  FUZZ_CHECK(seg.size() == m.face.size());
  FUZZ_CHECK(K >= 0);
  std::vector<char> used(size_t(K), 0);
  for (size_t f = 0; f < seg.size(); ++f) {
    if (m.face[f].IsD()) {
      FUZZ_CHECK(seg[f] == -1);
      continue;
    }
    FUZZ_CHECK(seg[f] >= 0 && seg[f] < K);
    used[size_t(seg[f])] = 1;
  }
  FUZZ_CHECK(std::all_of(used.begin(), used.end(), [](char u) { return u != 0; }));
}

inline void check_dense(const std::vector<int>& seg, int K)
{
  std::vector<char> used(size_t(std::max(K, 0)), 0);
  for (int s : seg) {
    FUZZ_CHECK(s >= -1 && s < K);
    if (s >= 0)
      used[size_t(s)] = 1;
  }
  FUZZ_CHECK(std::all_of(used.begin(), used.end(), [](char u) { return u != 0; }));
}

inline void check_fit(const FitResult& r)
{
  if (!r.status.ok())
    return;
  FUZZ_CHECK(primitive_is_valid(r.primitive));
  FUZZ_CHECK(std::isfinite(r.rms) && r.rms >= 0);
  FUZZ_CHECK(std::isfinite(r.max_residual) && r.max_residual >= 0);
}

template <class MeshType>
void check_adjacency(const MeshType& m, const FaceAdjacency& adj)
{
  FUZZ_CHECK(adj.face_count() == int(m.face.size()));
  FUZZ_CHECK(adj.offset.empty() || adj.offset.front() == 0);
  std::vector<std::pair<int, int>> pairs;
  for (int f = 0; f < adj.face_count(); ++f) {
    FUZZ_CHECK(adj.offset[size_t(f)] <= adj.offset[size_t(f) + 1]);
    for (int k = adj.offset[size_t(f)]; k < adj.offset[size_t(f) + 1]; ++k) {
      const int g = adj.neighbour[size_t(k)];
      FUZZ_CHECK(g >= 0 && g < adj.face_count() && g != f);
      FUZZ_CHECK(!m.face[size_t(f)].IsD() && !m.face[size_t(g)].IsD());
      pairs.emplace_back(f, g);
    }
  }
  FUZZ_CHECK(adj.offset.empty() || adj.offset.back() == int(adj.neighbour.size()));
  // Symmetric: g lists f whenever f lists g.
  std::vector<std::pair<int, int>> reversed;
  for (const auto& p : pairs)
    reversed.emplace_back(p.second, p.first);
  std::sort(pairs.begin(), pairs.end());
  std::sort(reversed.begin(), reversed.end());
  FUZZ_CHECK(pairs == reversed);
}

} // namespace fuzz

#endif
