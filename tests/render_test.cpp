// The preview renderer, checked on real pixels: small synthetic meshes drawn through OSMesa,
// the PNG decoded again with stb_image.
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
// Debian's libstb-dev: the implementation is in libstb, which knitc_render links.
#include <stb/stb_image.h>

#include "render.hpp"

namespace knitc::render {
namespace {

using Rgb = std::array<int, 3>;

struct Decoded {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  Rgb at(int x, int y) const {
    const auto i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

Decoded decode(const std::string& png_bytes) {
  Decoded d;
  int channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(png_bytes.data()),
                                          static_cast<int>(png_bytes.size()), &d.width, &d.height, &channels, 3);
  if (!pixels) throw std::runtime_error("not a PNG stb_image can read");
  d.rgb.assign(pixels, pixels + static_cast<std::size_t>(d.width) * static_cast<std::size_t>(d.height) * 3);
  stbi_image_free(pixels);
  return d;
}

int srgb8(float linear) {
  const float s = linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
  return static_cast<int>(std::lround(255.0f * s));
}

Rgb srgb8(glm::vec3 linear) { return {srgb8(linear.r), srgb8(linear.g), srgb8(linear.b)}; }

const glm::vec3 red{0.80f, 0.05f, 0.05f};
const glm::vec3 blue{0.04f, 0.08f, 0.70f};
const glm::vec3 green{0.05f, 0.60f, 0.08f};

int add_material(mesh::Mesh& m, glm::vec3 colour) {
  m.materials.push_back({"yarn" + std::to_string(m.materials.size()), colour});
  return static_cast<int>(m.materials.size()) - 1;
}

// An axis-aligned box as six quads with outward normals; the face toward +Z gets material
// `front`, the face toward -Z material `back`, the four sides material `sides`.
void add_box(mesh::Mesh& m, glm::vec3 lo, glm::vec3 hi, int front, int back, int sides) {
  const auto quad = [&](int material, glm::vec3 n, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    mesh::Primitive p;
    p.material = material;
    p.positions = {a, b, c, d};
    p.normals = {n, n, n, n};
    p.indices = {0, 1, 2, 0, 2, 3};
    m.primitives.push_back(std::move(p));
  };
  const glm::vec3 l = lo, h = hi;
  quad(front, {0, 0, 1}, {l.x, l.y, h.z}, {h.x, l.y, h.z}, {h.x, h.y, h.z}, {l.x, h.y, h.z});
  quad(back, {0, 0, -1}, {l.x, l.y, l.z}, {l.x, h.y, l.z}, {h.x, h.y, l.z}, {h.x, l.y, l.z});
  quad(sides, {1, 0, 0}, {h.x, l.y, l.z}, {h.x, h.y, l.z}, {h.x, h.y, h.z}, {h.x, l.y, h.z});
  quad(sides, {-1, 0, 0}, {l.x, l.y, l.z}, {l.x, l.y, h.z}, {l.x, h.y, h.z}, {l.x, h.y, l.z});
  quad(sides, {0, 1, 0}, {l.x, h.y, l.z}, {l.x, h.y, h.z}, {h.x, h.y, h.z}, {h.x, h.y, l.z});
  quad(sides, {0, -1, 0}, {l.x, l.y, l.z}, {h.x, l.y, l.z}, {h.x, l.y, h.z}, {l.x, l.y, h.z});
}

// A plus sign 20 mm by 15 mm in the XY plane, 1 mm thick: the corners of its box are empty.
mesh::Mesh cross(glm::vec3 colour) {
  mesh::Mesh m;
  const int c = add_material(m, colour);
  add_box(m, {-10.0f, -1.5f, -0.5f}, {10.0f, 1.5f, 0.5f}, c, c, c);
  add_box(m, {-2.0f, -7.5f, -0.5f}, {2.0f, 7.5f, 0.5f}, c, c, c);
  return m;
}

RenderOptions small(RenderOptions::Side side = RenderOptions::Side::face) {
  RenderOptions o;
  o.width = 160;
  o.height = 120;
  o.side = side;
  return o;
}

void expect_near(Rgb got, Rgb want, int tolerance, const char* where) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(got[static_cast<std::size_t>(c)], want[static_cast<std::size_t>(c)], tolerance)
        << where << " channel " << c;
}

TEST(Render, FaceShowsTheYarnColourInTheMiddleAndBackgroundInTheCorners) {
  const RenderOptions o = small();
  const Decoded img = decode(png(cross(red), o));
  ASSERT_EQ(img.width, 160);
  ASSERT_EQ(img.height, 120);
  // Facing the viewer, the lit colour is close to the colour the designer asked for.
  expect_near(img.at(80, 60), srgb8(red), 14, "centre");
  expect_near(img.at(20, 60), srgb8(red), 14, "left arm");
  expect_near(img.at(80, 15), srgb8(red), 14, "top arm");
  const Rgb background = srgb8(o.background);
  for (const auto& [x, y] : {std::pair{2, 2}, {157, 2}, {2, 117}, {157, 117}, {30, 25}})
    expect_near(img.at(x, y), background, 0, "corner");
}

TEST(Render, BackgroundOptionIsUsed) {
  RenderOptions o = small();
  o.background = {0.0f, 0.0f, 0.2f};
  const Decoded img = decode(png(cross(red), o));
  expect_near(img.at(3, 3), srgb8(o.background), 0, "corner");
}

TEST(Render, FaceAndBackShowTheirOwnSides) {
  mesh::Mesh m;
  const int r = add_material(m, red), b = add_material(m, blue);
  add_box(m, {-10.0f, -7.0f, -0.5f}, {10.0f, 7.0f, 0.5f}, r, b, r);
  const Decoded face = decode(png(m, small(RenderOptions::Side::face)));
  const Decoded back = decode(png(m, small(RenderOptions::Side::back)));
  const Rgb f = face.at(80, 60), k = back.at(80, 60);
  EXPECT_GT(f[0], f[2] + 100) << "face is red";
  EXPECT_GT(k[2], k[0] + 100) << "back is blue";
  expect_near(k, srgb8(blue), 14, "back centre");
}

TEST(Render, BackIsTheSwatchTurnedAroundItsVerticalAxis) {
  // A red bar on the left the full height, a blue block at the upper right.
  mesh::Mesh m;
  const int r = add_material(m, red), b = add_material(m, blue);
  add_box(m, {-10.0f, -7.5f, -0.5f}, {-2.0f, 7.5f, 0.5f}, r, r, r);
  add_box(m, {2.0f, 0.0f, -0.5f}, {10.0f, 7.5f, 0.5f}, b, b, b);
  const Rgb background = srgb8(small().background);

  const Decoded face = decode(png(m, small(RenderOptions::Side::face)));
  EXPECT_GT(face.at(40, 60)[0], 150) << "red bar on the left";
  EXPECT_GT(face.at(120, 30)[2], 150) << "blue block upper right";
  expect_near(face.at(120, 95), background, 0, "nothing lower right");

  const Decoded back = decode(png(m, small(RenderOptions::Side::back)));
  EXPECT_GT(back.at(120, 60)[0], 150) << "red bar now on the right";
  EXPECT_GT(back.at(40, 30)[2], 150) << "blue block upper left";
  expect_near(back.at(40, 95), background, 0, "nothing lower left");
}

TEST(Render, BothPutsFaceAndBackSideBySide) {
  mesh::Mesh m;
  const int r = add_material(m, red), b = add_material(m, blue), g = add_material(m, green);
  add_box(m, {-10.0f, -7.0f, -0.5f}, {0.0f, 7.0f, 0.5f}, r, b, r);
  add_box(m, {0.0f, -7.0f, -0.5f}, {10.0f, 2.0f, 0.5f}, g, b, g);
  const Decoded face = decode(png(m, small(RenderOptions::Side::face)));
  const Decoded back = decode(png(m, small(RenderOptions::Side::back)));
  const Decoded both = decode(png(m, small(RenderOptions::Side::both)));
  ASSERT_EQ(both.width, 320);
  ASSERT_EQ(both.height, 120);
  for (int y = 0; y < 120; y += 7)
    for (int x = 0; x < 160; x += 5) {
      ASSERT_EQ(both.at(x, y), face.at(x, y)) << x << ", " << y;
      ASSERT_EQ(both.at(160 + x, y), back.at(x, y)) << x << ", " << y;
    }
}

TEST(Render, SameInputSameBytes) {
  const mesh::Mesh m = cross(green);
  EXPECT_EQ(png(m, small()), png(m, small()));
  EXPECT_EQ(png(m, small(RenderOptions::Side::both)), png(m, small(RenderOptions::Side::both)));
}

TEST(Render, ImageChangesWithTheMesh) {
  const std::string a = png(cross(red), small());
  EXPECT_NE(a, png(cross(blue), small()));
  mesh::Mesh moved = cross(red);
  moved.primitives[0].positions[2].y += 3.0f;  // a corner of the horizontal bar's front
  EXPECT_NE(a, png(moved, small()));
}

TEST(Render, FlatShadingWithoutNormals) {
  mesh::Mesh m = cross(red);
  for (auto& p : m.primitives) p.normals.clear();
  const Decoded img = decode(png(m, small()));
  expect_near(img.at(80, 60), srgb8(red), 14, "centre");
}

TEST(Render, LinesAreDrawnInTheirColour) {
  mesh::Mesh m;
  const int g = add_material(m, green);
  mesh::Primitive strip;
  strip.material = g;
  strip.mode = mesh::Mode::line_strip;
  strip.positions = {{-10, -7.5f, 0}, {-10, 7.5f, 0}, {10, 7.5f, 0}, {10, -7.5f, 0}, {-10, -7.5f, 0}, {10, 7.5f, 0}};
  strip.indices = {0, 1, 2, 3, 4, 5};
  m.primitives.push_back(strip);
  const Decoded img = decode(png(m, small()));
  // The diagonal passes through the centre; look for a green pixel there.
  bool found = false;
  for (int y = 57; y <= 63; ++y)
    for (int x = 77; x <= 83; ++x) {
      const Rgb p = img.at(x, y);
      found = found || (p[1] > p[0] + 40 && p[1] > p[2] + 40);
    }
  EXPECT_TRUE(found);
  expect_near(img.at(80, 90), srgb8(small().background), 0, "off the lines");
}

TEST(Render, EmptyMeshIsAllBackground) {
  const RenderOptions o = small();
  const Decoded img = decode(png(mesh::Mesh{}, o));
  ASSERT_EQ(img.width, 160);
  const Rgb background = srgb8(o.background);
  for (int y = 0; y < 120; y += 13)
    for (int x = 0; x < 160; x += 11) ASSERT_EQ(img.at(x, y), background);
}

TEST(Render, SupersamplingSmoothsEdges) {
  RenderOptions o = small();
  o.samples = 1;
  const Decoded hard = decode(png(cross(red), o));
  o.samples = 16;
  const Decoded soft = decode(png(cross(red), o));
  // Count the pixels that are neither background nor the flat red: only edges are mixed.
  const auto mixed = [](const Decoded& d) {
    int n = 0;
    for (int y = 0; y < d.height; ++y)
      for (int x = 0; x < d.width; ++x) {
        const Rgb p = d.at(x, y);
        if (p[1] > 90 && p[1] < 200) ++n;
      }
    return n;
  };
  EXPECT_GT(mixed(soft), mixed(hard));
}

TEST(Render, MalformedMeshOrOptionsThrow) {
  mesh::Mesh m = cross(red);
  m.primitives[0].indices.push_back(99);
  EXPECT_THROW(png(m, small()), std::runtime_error);
  m = cross(red);
  m.primitives[0].material = 5;
  EXPECT_THROW(png(m, small()), std::runtime_error);
  RenderOptions o = small();
  o.width = 0;
  EXPECT_THROW(png(cross(red), o), std::runtime_error);
}

}  // namespace
}  // namespace knitc::render
