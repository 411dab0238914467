// viewer/vertex_formats.hpp — the interleaved float vertices of the viewer's
// two shader programs (shaders/viewer_mesh.*, shaders/viewer_points.*).
//
// MeshVertices: position (3, mm or panel units), normal (3, unit), colour
// (4, RGBA in [0, 1]), scalar (1, e.g. displacement modulus in mm); drawn as
// indexed triangles. PointVertices: position (3), colour (4), style (2:
// diameter in pixels, ring flag); drawn as points or as line pairs.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace onetip::viewer {

using Rgba = Eigen::Vector4f;

struct MeshVertices {
  static constexpr int kFloats = 11;
  static std::vector<int> layout() { return {3, 3, 4, 1}; }
  std::vector<float> data;
  std::vector<unsigned> indices;

  int count() const noexcept { return static_cast<int>(data.size()) / kFloats; }
  void add(const Eigen::Vector3f& p, const Eigen::Vector3f& n, const Rgba& c, float scalar) {
    for (float v : {p.x(), p.y(), p.z(), n.x(), n.y(), n.z(), c[0], c[1], c[2], c[3], scalar}) data.push_back(v);
  }
  Eigen::Vector3f position(int i) const { return Eigen::Vector3f(&data[static_cast<size_t>(i * kFloats)]); }
  float scalar(int i) const { return data[static_cast<size_t>(i * kFloats + 10)]; }
};

struct PointVertices {
  static constexpr int kFloats = 9;
  static std::vector<int> layout() { return {3, 4, 2}; }
  std::vector<float> data;

  int count() const noexcept { return static_cast<int>(data.size()) / kFloats; }
  void add(const Eigen::Vector3f& p, const Rgba& c, float diameter_px = 1.0F, bool ring = false) {
    for (float v : {p.x(), p.y(), p.z(), c[0], c[1], c[2], c[3], diameter_px, ring ? 1.0F : 0.0F}) data.push_back(v);
  }
  // A line segment (two vertices, for GL_LINES).
  void addLine(const Eigen::Vector3f& a, const Eigen::Vector3f& b, const Rgba& c) {
    add(a, c);
    add(b, c);
  }
  Eigen::Vector3f position(int i) const { return Eigen::Vector3f(&data[static_cast<size_t>(i * kFloats)]); }
  Rgba colour(int i) const { return Rgba(&data[static_cast<size_t>(i * kFloats + 3)]); }
  bool ring(int i) const { return data[static_cast<size_t>(i * kFloats + 8)] > 0.5F; }
};

}  // namespace onetip::viewer
