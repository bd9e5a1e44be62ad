// The sweep: samples placed by the chord-error tolerance, frames that stay orthonormal
// and do not flip, and tubes that are closed, two-manifold and facing out.
#include <cmath>
#include <map>
#include <numbers>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "support.hpp"
#include "topology.hpp"

namespace knitc {
namespace {

using yarn_paths::LoopModel;

// Distance from p to the segment ab.
double to_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::distance(p, a + t * ab);
}

TEST(Sampling, ChordErrorStaysWithinTheTolerance) {
  for (double tolerance : {0.05, 0.01, 0.002}) {
    CompileOptions o;
    o.chord_tolerance = tolerance;
    const double d = 1.0;
    const Fabric f = compile(test::jersey(4, 2, 4.0, 4.2, 2.0, d), o);
    double worst = 0.0;
    for (const auto& piece : f.pieces) {
      const auto& u = piece.samples;
      for (std::size_t i = 0; i + 1 < u.size(); ++i) {
        for (int k = 1; k < 8; ++k) {
          const glm::dvec3 p = nurbs::evaluate(piece.curve.curve, u[i] + (u[i + 1] - u[i]) * k / 8.0);
          worst = std::max(worst, to_segment(p, piece.frames.origin[i], piece.frames.origin[i + 1]));
        }
      }
    }
    // The centreline's chord error is below the outer fibre's, which the tolerance bounds.
    EXPECT_LE(worst, tolerance * d * 1.02) << "tolerance " << tolerance;
    EXPECT_GT(worst, tolerance * d * 0.2) << "far more samples than the tolerance needs";
  }
}

TEST(Sampling, SampleCountGrowsAsTheInverseSquareRootOfTheTolerance) {
  auto count = [](double tolerance) {
    CompileOptions o;
    o.chord_tolerance = tolerance;
    std::size_t n = 0;
    for (const auto& piece : compile(test::jersey(6, 3), o).pieces) n += piece.samples.size();
    return static_cast<double>(n);
  };
  const double ratio = count(0.0025) / count(0.04);  // tolerance / 16: about 4x the samples
  EXPECT_GT(ratio, 3.5);
  EXPECT_LT(ratio, 4.5);
}

TEST(Sampling, StraightSegmentNeedsNoInteriorSamples) {
  const std::vector<glm::dvec3> line = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
  const auto curve = nurbs::interpolate(line).curve;
  const auto u = sweep::sample_parameters(curve, 0.0, 1.0, 0.01, 0.5);
  EXPECT_EQ(u.size(), 2u);
}

TEST(Frames, AreOrthonormalAndRotationMinimisingFramesDoNotFlip) {
  const Fabric f = compile(test::jersey(8, 2), CompileOptions{});
  double largest_turn = 0.0;
  for (const auto& piece : f.pieces) {
    const auto& fr = piece.frames;
    for (std::size_t i = 0; i < fr.size(); ++i) {
      EXPECT_NEAR(glm::length(fr.tangent[i]), 1.0, 1e-12);
      EXPECT_NEAR(glm::length(fr.normal[i]), 1.0, 1e-12);
      EXPECT_NEAR(glm::dot(fr.tangent[i], fr.normal[i]), 0.0, 1e-12);
      EXPECT_NEAR(glm::dot(fr.binormal[i], glm::cross(fr.tangent[i], fr.normal[i])), 1.0, 1e-12);
      if (i + 1 < fr.size()) {
        // The normal turns no more than the tangent does between two samples, plus a little.
        const double tangent_turn = std::acos(std::clamp(glm::dot(fr.tangent[i], fr.tangent[i + 1]), -1.0, 1.0));
        const double normal_turn = std::acos(std::clamp(glm::dot(fr.normal[i], fr.normal[i + 1]), -1.0, 1.0));
        EXPECT_LE(normal_turn, tangent_turn + 1e-4);
        largest_turn = std::max(largest_turn, normal_turn);
      }
    }
  }
  EXPECT_LT(largest_turn * 180.0 / std::numbers::pi, 30.0);
}

TEST(Frames, RotationMinimisingFrameHasNoTwistOnAPlanarCurve) {
  // On a plane curve the rotation-minimising normal stays in or perpendicular to the plane.
  std::vector<glm::dvec3> wave;
  for (int i = 0; i <= 40; ++i) wave.emplace_back(i * 0.5, std::sin(i * 0.5), 0.0);
  const auto curve = nurbs::interpolate(wave).curve;
  const auto u = sweep::sample_parameters(curve, 0.0, 1.0, 0.001, 0.0);
  const auto fr = sweep::frames(curve, u, sweep::FrameKind::rotation_minimising);
  const double z0 = fr.normal[0].z;
  for (std::size_t i = 0; i < fr.size(); ++i) EXPECT_NEAR(std::abs(fr.normal[i].z), std::abs(z0), 1e-6);
}


// A jersey swatch in the given yarn.
Pattern swatch(const std::string& yarn) {
  return runtime::run_pattern("pattern { gauge = { loop_width = 4.5, loop_height = 4.8, thickness = 2.4 }, yarns = { A = " +
                                  yarn + " }, knitting = \"flat\" }\ncast_on(5)\nrows(4, \"k\")\n",
                              "t.lua")
      .pattern;
}

TEST(Tube, EveryYarnTubeIsClosedTwoManifoldAndFacesOut) {
  const std::pair<const char*, int> yarns[] = {
      {"{ diameter = 1.2 }", 1},
      {"{ diameter = 1.2, section = \"ellipse\", aspect = 0.5 }", 1},
      {"{ diameter = 1.2, section = \"plied\", plies = 3, twist = 20, direction = \"Z\" }", 3},
  };
  for (const auto& [yarn, strands_per_piece] : yarns) {
    const Pattern pattern = swatch(yarn);
    for (const auto model : {LoopModel::smooth, LoopModel::paper}) {
      SCOPED_TRACE(std::string(yarn) + (model == LoopModel::paper ? " paper" : " smooth"));
      CompileOptions o;
      o.loop_model = model;
      o.sides = 9;
      const Fabric f = compile(pattern, o);
      ASSERT_EQ(f.mesh.primitives.size(), 1u);
      const double r = 0.6;
      std::size_t vertices = 0, indices = 0;
      for (const auto& piece : f.pieces) {
        // Each strand's tube alone (in paper mode neighbouring loops' caps touch, so
        // welding the whole primitive would join them).
        const auto strands = sweep::strands(piece.frames, piece.arc_length, tubes::cross_section(pattern.yarns[0]));
        ASSERT_EQ(strands.size(), static_cast<std::size_t>(strands_per_piece));
        const int sides = strands_per_piece > 1 ? 5 : 9;
        for (const auto& strand : strands) {
          mesh::Primitive tube;
          sweep::append_tubes(std::span(&strand, 1), piece.arc_length, sides, tube);
          vertices += tube.positions.size();
          indices += tube.indices.size();
          const test::TopologyReport t = test::topology(tube);
          EXPECT_EQ(t.non_manifold_edges, 0u);
          EXPECT_EQ(t.inconsistent_edges, 0u);
          EXPECT_EQ(t.components, 1u);
          // A sphere topologically: V - E + F = 2.
          EXPECT_EQ(static_cast<long long>(t.welded_vertices) - static_cast<long long>(t.edges) +
                        static_cast<long long>(t.triangles), 2);
          // Outward: the enclosed volume is positive and close to the polygon's area times
          // the strand's length (an n-gon in an ellipse of half-axes a, b holds n/2 sin(2 pi/n) a b).
          double length = 0.0;
          for (std::size_t i = 1; i < strand.frames.size(); ++i)
            length += glm::distance(strand.frames.origin[i], strand.frames.origin[i - 1]);
          const double polygon = sides / 2.0 * std::sin(2.0 * std::numbers::pi / sides) * strand.along_normal * strand.along_binormal;
          EXPECT_NEAR(t.signed_volume, polygon * length, 0.03 * polygon * length);
          EXPECT_LE(std::max(strand.along_normal, strand.along_binormal), r / std::sqrt(0.5) + 1e-12);
        }
      }
      const auto& prim = f.mesh.primitives[0];
      EXPECT_EQ(prim.positions.size(), vertices);
      EXPECT_EQ(prim.indices.size(), indices);
      ASSERT_EQ(prim.uvs.size(), prim.positions.size());
      // Vertex normals are unit and agree with their triangles' winding.
      for (const auto& n : prim.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
      std::size_t against = 0;
      for (std::size_t t = 0; t < prim.indices.size(); t += 3) {
        const glm::vec3 a = prim.positions[prim.indices[t]], b = prim.positions[prim.indices[t + 1]],
                        c = prim.positions[prim.indices[t + 2]];
        const glm::vec3 face = glm::cross(b - a, c - a);
        for (int k = 0; k < 3; ++k) against += glm::dot(face, prim.normals[prim.indices[t + k]]) <= 0.0f;
      }
      EXPECT_EQ(against, 0u);
    }
  }
}

TEST(Tube, TextureCoordinatesRunAlongTheYarnInMillimetres) {
  const Fabric f = compile(swatch("{ diameter = 1 }"), CompileOptions{});
  const auto& piece = f.pieces[0];
  EXPECT_EQ(piece.arc_length.front(), 0.0);
  EXPECT_NEAR(piece.arc_length.back(), nurbs::arc_length(piece.curve.curve, 0.0, 1.0), 1e-9);
  // u grows with the yarn's length from ring to ring, with no jump at loop joins.
  const auto& uvs = f.mesh.primitives[0].uvs;
  const int stride = 13;  // 12 sides and the seam
  for (std::size_t i = 1; i < piece.frames.size(); ++i) {
    const float du = uvs[i * stride].x - uvs[(i - 1) * stride].x;
    EXPECT_GT(du, 0.0f);
    EXPECT_NEAR(du, glm::distance(piece.frames.origin[i], piece.frames.origin[i - 1]), 0.01);
    EXPECT_EQ(uvs[i * stride].y, 0.0f);
    EXPECT_EQ(uvs[i * stride + 12].y, 1.0f);
  }
}

TEST(Tube, PliesTwistAsAskedAndStayInsideTheYarn) {
  const Pattern p = swatch("{ diameter = 1.2, section = \"plied\", plies = 2, twist = 10, direction = \"S\" }");
  const Fabric f = compile(p, CompileOptions{});
  const auto& piece = f.pieces[0];
  const auto strands = sweep::strands(piece.frames, piece.arc_length, tubes::cross_section(p.yarns[0]));
  ASSERT_EQ(strands.size(), 2u);
  // Two plies of a quarter of the width, their centres a quarter of the width off the axis.
  EXPECT_NEAR(strands[0].along_normal, 0.3, 1e-12);
  for (std::size_t i = 0; i < piece.frames.size(); ++i) {
    const glm::dvec3 off = strands[0].frames.origin[i] - piece.frames.origin[i];
    EXPECT_NEAR(glm::length(off), 0.3, 1e-9);
    EXPECT_NEAR(glm::dot(off, piece.frames.tangent[i]), 0.0, 1e-9);
    // The angle in the rotation-minimising frame turns 10 times per 100 mm, S: clockwise.
    const double angle = std::atan2(glm::dot(off, piece.frames.binormal[i]), glm::dot(off, piece.frames.normal[i]));
    const double expected = -2.0 * std::numbers::pi * 0.1 * piece.arc_length[i];
    EXPECT_NEAR(std::remainder(angle - expected, 2.0 * std::numbers::pi), 0.0, 1e-9);
  }
  // Samples come often enough for the helix: 12 per turn at least.
  for (std::size_t i = 1; i < piece.arc_length.size(); ++i) EXPECT_LE(piece.arc_length[i] - piece.arc_length[i - 1], 10.0 / 12.0 + 1e-6);
}

// A round yarn pressed (relax/press.hpp) flattens to an ellipse of its own area, its
// minor axis along the pressing; where the pressing turns half a turn (the same ellipse)
// the ring does not spin, and where it stops the ring turns back round.
TEST(Tube, APressedRoundYarnFlattensAcrossThePressingKeepingItsArea) {
  sweep::Frames f;
  std::vector<double> s;
  std::vector<glm::dvec3> pressed;
  const glm::dvec3 at_45 = glm::normalize(glm::dvec3(0.0, 1.0, 1.0));
  for (int i = 0; i < 8; ++i) {
    f.origin.push_back({i * 0.5, 0.0, 0.0});
    f.tangent.push_back({1.0, 0.0, 0.0});
    f.normal.push_back({0.0, 1.0, 0.0});
    f.binormal.push_back({0.0, 0.0, 1.0});
    s.push_back(i * 0.5);
    pressed.push_back(i < 6 ? (i % 2 ? -0.36 : 0.36) * at_45 : glm::dvec3(0.0));  // aspect 0.64, then round
  }
  sweep::CrossSection round;
  round.radius = 0.5;
  const auto strands = sweep::strands(f, s, round, pressed);
  ASSERT_EQ(strands.size(), 1u);
  mesh::Primitive prim;
  prim.mode = mesh::Mode::triangles;
  const int sides = 64;
  sweep::append_tubes(strands, s, sides, prim);
  for (int i = 0; i < 8; ++i) {
    // The ring's extent along the pressing and across it, and its area (a polygon).
    double along = 0.0, across = 0.0, area = 0.0;
    const glm::dvec3 other = glm::cross(glm::dvec3(1, 0, 0), at_45);
    for (int k = 0; k < sides; ++k) {
      const glm::dvec3 p = glm::dvec3(prim.positions[static_cast<std::size_t>(i * (sides + 1) + k)]) - f.origin[static_cast<std::size_t>(i)];
      const glm::dvec3 q = glm::dvec3(prim.positions[static_cast<std::size_t>(i * (sides + 1) + (k + 1) % sides)]) - f.origin[static_cast<std::size_t>(i)];
      along = std::max(along, std::abs(glm::dot(p, at_45)));
      across = std::max(across, std::abs(glm::dot(p, other)));
      area += 0.5 * glm::dot(glm::cross(p, q), glm::dvec3(1, 0, 0));
    }
    const double expected_area = std::numbers::pi * 0.25 * std::sin(2 * std::numbers::pi / sides) * sides / (2 * std::numbers::pi);
    EXPECT_NEAR(area, expected_area, 1e-4) << "ring " << i;
    if (i < 6) {
      EXPECT_NEAR(along, 0.5 * 0.8, 1e-3) << "ring " << i;   // r sqrt(aspect)
      EXPECT_NEAR(across, 0.5 / 0.8, 1e-3) << "ring " << i;  // r / sqrt(aspect)
    } else {
      EXPECT_NEAR(along, 0.5, 1e-3) << "ring " << i;
      EXPECT_NEAR(across, 0.5, 1e-3) << "ring " << i;
    }
    // The frame turns only to follow the pressing: not half a turn where its sign flips.
    if (i > 0) {
      const auto& n = strands[0].frames.normal;
      EXPECT_GT(glm::dot(n[static_cast<std::size_t>(i)], n[static_cast<std::size_t>(i - 1)]), 0.99) << "ring " << i;
    }
  }
  // No pressing given: the round tube as ever.
  EXPECT_TRUE(sweep::strands(f, s, round)[0].axes.empty());
}

// Plies pressed flat: their centres spread onto the pressed section's ellipse (the plies'
// own radius kept), while their twist keeps the frame's phase; unpressed, the helix as ever.
TEST(Tube, PressedPliesSpreadAlongTheMajorAxis) {
  sweep::Frames f;
  std::vector<double> s;
  std::vector<glm::dvec3> pressed;
  for (int i = 0; i < 41; ++i) {
    f.origin.push_back({i * 0.25, 0.0, 0.0});
    f.tangent.push_back({1.0, 0.0, 0.0});
    f.normal.push_back({0.0, 1.0, 0.0});
    f.binormal.push_back({0.0, 0.0, 1.0});
    s.push_back(i * 0.25);
    pressed.push_back({0.0, 0.0, 0.36});  // pressed along z, aspect 0.64
  }
  sweep::CrossSection plied;
  plied.shape = sweep::CrossSection::Shape::plied;
  plied.radius = 0.5;
  plied.plies = 2;
  plied.twist = 0.1;  // a turn every 10 mm: the 10 mm piece turns once
  const auto flat = sweep::strands(f, s, plied, pressed), round = sweep::strands(f, s, plied);
  ASSERT_EQ(flat.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    double y = 0.0, z = 0.0, y0 = 0.0, z0 = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const glm::dvec3 d = flat[k].frames.origin[i] - f.origin[i], d0 = round[k].frames.origin[i] - f.origin[i];
      y = std::max(y, std::abs(d.y)), z = std::max(z, std::abs(d.z));
      y0 = std::max(y0, std::abs(d0.y)), z0 = std::max(z0, std::abs(d0.z));
    }
    EXPECT_NEAR(y0, 0.25, 1e-3);  // two touching plies: centres at half the radius
    EXPECT_NEAR(z0, 0.25, 1e-3);
    EXPECT_NEAR(y, 0.25 / 0.8, 1e-3);  // across the pressing: over sqrt(aspect)
    EXPECT_NEAR(z, 0.25 * 0.8, 1e-3);  // along it: times sqrt(aspect)
    EXPECT_EQ(flat[k].along_normal, round[k].along_normal);
  }
}

TEST(Tube, WireframeHasRingsAndLongEdges) {
  CompileOptions o;
  o.view = View::wireframe;
  o.sides = 6;
  const Fabric f = compile(test::jersey(2, 1), o);
  ASSERT_EQ(f.mesh.primitives.size(), 1u);
  const auto& prim = f.mesh.primitives[0];
  EXPECT_EQ(prim.mode, mesh::Mode::lines);
  const std::size_t rings = f.pieces[0].frames.size();
  EXPECT_EQ(prim.positions.size(), rings * 6);
  EXPECT_EQ(prim.indices.size(), 2 * (rings * 6 + (rings - 1) * 6));
}

TEST(Tube, CentrelineViewIsALineStripPerPiece) {
  CompileOptions o;
  o.view = View::centreline;
  const Fabric f = compile(test::jersey(3, 4), o);
  ASSERT_EQ(f.pieces.size(), 1u);  // the yarn runs through every course
  ASSERT_EQ(f.mesh.primitives.size(), f.pieces.size());
  for (std::size_t i = 0; i < f.pieces.size(); ++i) {
    EXPECT_EQ(f.mesh.primitives[i].mode, mesh::Mode::line_strip);
    EXPECT_EQ(f.mesh.primitives[i].positions.size(), f.pieces[i].samples.size());
  }
}

}  // namespace
}  // namespace knitc
