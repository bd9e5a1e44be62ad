// The traced preview, on real pixels: synthetic scenes whose shadows and occlusion are
// known, traced with Embree and decoded again with stb_image; and its determinism.
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <stb/stb_image.h>

#include "mesh/bounds.hpp"
#include "trace.hpp"

namespace knitc::render {
namespace {

struct Decoded {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  // The mean linear brightness (green channel) of the 5 x 5 pixels about p.
  double around(glm::vec2 p) const {
    double sum = 0.0;
    const int cx = static_cast<int>(std::lround(p.x - 0.5f)), cy = static_cast<int>(std::lround(p.y - 0.5f));
    for (int y = cy - 2; y <= cy + 2; ++y)
      for (int x = cx - 2; x <= cx + 2; ++x) {
        EXPECT_TRUE(x >= 0 && y >= 0 && x < width && y < height);
        const double s = rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3 + 1] / 255.0;
        sum += s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
      }
    return sum / 25.0;
  }
};

Decoded decode(const std::string& png) {
  Decoded d;
  int channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(png.data()), static_cast<int>(png.size()), &d.width,
                                          &d.height, &channels, 3);
  if (!pixels) throw std::runtime_error("not a PNG stb_image can read");
  d.rgb.assign(pixels, pixels + static_cast<std::size_t>(d.width) * static_cast<std::size_t>(d.height) * 3);
  stbi_image_free(pixels);
  return d;
}

int material(mesh::Mesh& m, glm::vec3 colour) {
  m.materials.push_back({"m" + std::to_string(m.materials.size()), colour, glm::vec3(0.0f), 0.5f});
  return static_cast<int>(m.materials.size()) - 1;
}

// A quad facing +Z at height z over [x0, x1] x [y0, y1].
void add_quad(mesh::Mesh& m, int mat, float x0, float y0, float x1, float y1, float z) {
  mesh::Primitive p;
  p.material = mat;
  p.positions = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
  p.normals.assign(4, glm::vec3(0, 0, 1));
  p.indices = {0, 1, 2, 0, 2, 3};
  m.primitives.push_back(std::move(p));
}

// A torus (a ring of yarn): centre c, its axis `axis`, major radius R, tube radius r.
void add_ring(mesh::Mesh& m, int mat, glm::vec3 c, glm::vec3 axis, float R, float r) {
  const glm::vec3 a = glm::normalize(axis);
  const glm::vec3 e1 = glm::normalize(glm::cross(a, std::abs(a.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
  const glm::vec3 e2 = glm::cross(a, e1);
  mesh::Primitive p;
  p.material = mat;
  const int n = 96, k = 24;
  for (int i = 0; i < n; ++i) {
    const float t = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / n;
    const glm::vec3 radial = std::cos(t) * e1 + std::sin(t) * e2;
    for (int j = 0; j < k; ++j) {
      const float s = 2.0f * std::numbers::pi_v<float> * static_cast<float>(j) / k;
      const glm::vec3 normal = std::cos(s) * radial + std::sin(s) * a;
      p.positions.push_back(c + R * radial + r * normal);
      p.normals.push_back(normal);
    }
  }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < k; ++j) {
      const auto v = [&](int ii, int jj) { return static_cast<std::uint32_t>((ii % n) * k + (jj % k)); };
      p.indices.insert(p.indices.end(), {v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j), v(i + 1, j + 1), v(i, j + 1)});
    }
  m.primitives.push_back(std::move(p));
}

TEST(Traced, AShadowFallsAwayFromTheKeyLight) {
  // A card held 3 mm over a sheet: the key light (upper left, in front) casts its shadow
  // down and to the right, by 3 mm x (0.64, -0.79).
  mesh::Mesh m;
  const int grey = material(m, glm::vec3(0.6f));
  add_quad(m, grey, -10, -10, 10, 10, 0);
  add_quad(m, grey, -2, -2, 2, 2, 3);
  TraceOptions o;
  o.width = o.height = 200;
  o.samples = 16;
  const Decoded img = decode(traced_png(m, o));
  const mesh::Bounds box = mesh::bounds(m);
  const double shadow = img.around(traced_pixel(box, o, false, {2.5f, -3.2f, 0.0f}));
  const double open = img.around(traced_pixel(box, o, false, {-6.0f, 6.0f, 0.0f}));
  const double mirror = img.around(traced_pixel(box, o, false, {-2.5f, 3.2f, 0.0f}));  // the lit side of the card
  std::printf("shadow %.3f, beside the card on the lit side %.3f, open %.3f\n", shadow, mirror, open);
  EXPECT_LT(shadow, 0.6 * open);
  EXPECT_GT(mirror, 0.85 * open);
  EXPECT_NEAR(open, 0.6 * (0.8 * 0.7 + 0.4), 0.06);  // key x cos + sky, of the base colour
}

TEST(Traced, YarnInsideAnInterlockIsDarkerThanTheSameYarnInOpenLight) {
  // Ring A lies flat; ring B stands through it at x = 5, hugging A's tube. The top of A's
  // tube (facing the camera) beside B sees less sky than the top of A far from B.
  mesh::Mesh m;
  const int yarn = material(m, glm::vec3(0.7f, 0.6f, 0.45f));
  add_ring(m, yarn, {0, 0, 0}, {0, 0, 1}, 5.0f, 1.0f);
  add_ring(m, yarn, {5, 0, 0}, {0, 1, 0}, 2.2f, 1.0f);
  TraceOptions o;
  o.width = o.height = 240;
  o.samples = 64;
  const Decoded img = decode(traced_png(m, o));
  const mesh::Bounds box = mesh::bounds(m);
  const float theta = 0.32f;  // beside B's tube as the camera sees it, not under it
  const glm::vec3 inside{5.0f * std::cos(theta), 5.0f * std::sin(theta), 1.0f};
  const glm::vec3 outside{5.0f * std::cos(std::numbers::pi_v<float> - theta), 5.0f * std::sin(std::numbers::pi_v<float> - theta), 1.0f};
  const double in = img.around(traced_pixel(box, o, false, inside)), out = img.around(traced_pixel(box, o, false, outside));
  std::printf("top of the yarn inside the interlock %.3f, in open light %.3f\n", in, out);
  EXPECT_LT(in, 0.92 * out);
}

// Fibres are translucent: a screen of touching black fibres 3 mm over a sheet lets the
// sheet show through it, and casts a lighter shadow than a card there would.
TEST(Traced, FibresLetSomeLightThrough) {
  const auto scene = [](bool fibres) {
    mesh::Mesh m;
    const int grey = material(m, glm::vec3(0.6f)), black = material(m, glm::vec3(0.0f));
    add_quad(m, grey, -10, -10, 10, 10, 0);
    if (!fibres) {
      add_quad(m, black, -2, -2, 2, 2, 3);
      return m;
    }
    mesh::Primitive p;
    p.material = black;
    p.mode = mesh::Mode::lines;
    p.line_radius = 0.05f;
    for (float y = -2.0f; y <= 2.0f; y += 0.1f) {  // touching: seen square on, the screen is closed
      p.indices.push_back(static_cast<std::uint32_t>(p.positions.size()));
      p.positions.push_back({-2.0f, y, 3.0f});
      p.indices.push_back(static_cast<std::uint32_t>(p.positions.size()));
      p.positions.push_back({2.0f, y, 3.0f});
    }
    m.primitives.push_back(std::move(p));
    return m;
  };
  TraceOptions o;
  o.width = o.height = 200;
  o.samples = 64;
  const mesh::Mesh card = scene(false), screen = scene(true);
  const Decoded with_card = decode(traced_png(card, o)), with_screen = decode(traced_png(screen, o));
  const mesh::Bounds box = mesh::bounds(card);
  const glm::vec2 shadow_at = traced_pixel(box, o, false, {2.5f, -3.2f, 0.0f}), middle = traced_pixel(box, o, false, {0.0f, 0.0f, 3.0f});
  const double card_shadow = with_card.around(shadow_at), screen_shadow = with_screen.around(shadow_at);
  const double card_middle = with_card.around(middle), screen_middle = with_screen.around(middle);
  std::printf("shadow: card %.3f, screen of fibres %.3f; seen through: card %.3f, screen %.3f\n", card_shadow, screen_shadow,
              card_middle, screen_middle);
  EXPECT_GT(screen_shadow, card_shadow + 0.05);
  EXPECT_LT(card_middle, 0.02);    // a black card hides the sheet
  EXPECT_GT(screen_middle, 0.05);  // the sheet shows through the fibres
  // Which rays pass is hashed from the ray and the fibre: the same bytes for any thread count.
  o.samples = 4;
  o.threads = 1;
  const std::string one = traced_png(screen, o);
  o.threads = 2;
  EXPECT_EQ(one, traced_png(screen, o));
}

TEST(Traced, TheSameBytesForAnyThreadCountAndSeedDecidesTheNoise) {
  mesh::Mesh m;
  const int yarn = material(m, glm::vec3(0.7f, 0.3f, 0.2f));
  add_ring(m, yarn, {0, 0, 0}, {0, 0, 1}, 5.0f, 1.0f);
  add_ring(m, yarn, {5, 0, 0}, {0, 1, 0}, 2.2f, 1.0f);
  TraceOptions o;
  o.width = 160;
  o.height = 120;
  o.samples = 4;
  o.side = TraceOptions::Side::both;
  o.threads = 1;
  const std::string one = traced_png(m, o);
  o.threads = 2;
  EXPECT_EQ(traced_png(m, o), one);
  o.threads = 3;
  EXPECT_EQ(traced_png(m, o), one);
  o.seed = 2;
  EXPECT_NE(traced_png(m, o), one);
}

TEST(Traced, InstancesAreDrawnWhereTheyArePlaced) {
  // One ring meshed once and placed twice draws as the two rings drawn plainly.
  mesh::Mesh plain, instanced;
  const int a = material(plain, glm::vec3(0.5f));
  material(instanced, glm::vec3(0.5f));
  add_ring(plain, a, {-6, 0, 0}, {0, 0, 1}, 4.0f, 1.0f);
  add_ring(plain, a, {6, 0, 0}, {0, 0, 1}, 4.0f, 1.0f);
  mesh::Mesh tile;
  add_ring(tile, 0, {0, 0, 0}, {0, 0, 1}, 4.0f, 1.0f);
  instanced.instanced.push_back({tile.primitives, {{-6, 0, 0}, {6, 0, 0}}});
  TraceOptions o;
  o.width = 160;
  o.height = 80;
  o.samples = 4;
  EXPECT_EQ(traced_png(instanced, o), traced_png(plain, o));
}

TEST(Traced, RefusesWhatItCannotDraw) {
  mesh::Mesh m;
  TraceOptions o;
  o.samples = 0;
  EXPECT_THROW(traced_png(m, o), std::runtime_error);
  o.samples = 4;
  o.width = 0;
  EXPECT_THROW(traced_png(m, o), std::runtime_error);
  o.width = 16;
  o.close_up = std::nan("");
  EXPECT_THROW(traced_png(m, o), std::runtime_error);
  o.close_up = 0.0;
  mesh::Primitive bad;
  bad.positions = {{0, 0, 0}};
  bad.indices = {0, 1, 2};
  m.materials.push_back({});
  m.primitives.push_back(bad);
  EXPECT_THROW(traced_png(m, o), std::runtime_error);
  // An empty mesh is only the background.
  const Decoded img = decode(traced_png(mesh::Mesh{}, o));
  EXPECT_EQ(img.width, 16);
}

}  // namespace
}  // namespace knitc::render
