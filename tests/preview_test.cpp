// Previews of real fabrics, checked on their pixels: the yarn's colour where the fabric
// is, background elsewhere, face and back different, and a changed pattern changes
// the picture.
#include <cmath>

#include <gtest/gtest.h>
#include <stb/stb_image.h>

#include "render.hpp"
#include "support.hpp"

namespace knitc {
namespace {

struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  const unsigned char* at(int x, int y) const { return &rgb[3 * (static_cast<std::size_t>(y) * width + x)]; }
};

// Eight rows of stockinette, flat.
const std::string kJersey8 = "for i = 1, 8 do row(i % 2 == 1 and \"k\" or \"p\") end";

Image preview(const std::string& yarn, const std::string& rows, render::RenderOptions::Side side) {
  const Pattern p = runtime::run_pattern("pattern { gauge = { loop_width = 4, loop_height = 4.2, thickness = 2 }, yarns = { A = " +
                                             yarn + " }, knitting = \"flat\" }\ncast_on(8)\n" + rows + "\n",
                                         "t.lua")
                        .pattern;
  CompileOptions o;
  o.sides = 8;
  o.chord_tolerance = 0.05;
  render::RenderOptions r;
  r.width = 160;
  r.height = 120;
  r.side = side;
  const std::string png = render::png(compile(p, o).mesh, r);
  Image image;
  int channels = 0;
  unsigned char* data = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(png.data()),
                                              static_cast<int>(png.size()), &image.width, &image.height, &channels, 3);
  EXPECT_NE(data, nullptr);
  if (data != nullptr) {
    image.rgb.assign(data, data + 3 * static_cast<std::size_t>(image.width) * image.height);
    stbi_image_free(data);
  }
  return image;
}

bool is_background(const unsigned char* p) {
  return std::abs(p[0] - p[1]) < 4 && std::abs(p[1] - p[2]) < 4 && p[0] > 200;  // the light grey
}

TEST(Preview, OneColourSwatchIsThatColourWhereTheFabricIs) {
  const Image img = preview("{ diameter = 1, color = \"#c03020\" }", kJersey8, render::RenderOptions::Side::face);
  ASSERT_EQ(img.width, 160);
  int fabric = 0, reddish = 0;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const unsigned char* p = img.at(x, y);
      if (is_background(p)) continue;
      ++fabric;
      // Lit, shaded or blended with the background at an edge, the hue stays red.
      reddish += p[0] > p[1] + 12 && p[0] > p[2] + 12;
    }
  }
  EXPECT_GT(fabric, img.width * img.height / 4);  // the swatch fills the frame
  EXPECT_GT(reddish, fabric * 9 / 10);
  for (auto [x, y] : {std::pair{0, 0}, {159, 0}, {0, 119}, {159, 119}}) EXPECT_TRUE(is_background(img.at(x, y)));
}

double difference(const Image& a, const Image& b) {
  if (a.rgb.size() != b.rgb.size()) return 255.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) sum += std::abs(a.rgb[i] - b.rgb[i]);
  return sum / static_cast<double>(a.rgb.size());
}

TEST(Preview, FaceAndBackOfJerseyDiffer) {
  const std::string yarn = "{ diameter = 1, color = \"#d9c8a9\" }";
  const Image face = preview(yarn, kJersey8, render::RenderOptions::Side::face);
  const Image back = preview(yarn, kJersey8, render::RenderOptions::Side::back);
  const Image again = preview(yarn, kJersey8, render::RenderOptions::Side::face);
  EXPECT_EQ(difference(face, again), 0.0);
  EXPECT_GT(difference(face, back), 2.0);
}

TEST(Preview, TheImageChangesWithThePattern) {
  const Image jersey = preview("{ diameter = 1 }", kJersey8, render::RenderOptions::Side::face);
  const Image rib = preview("{ diameter = 1 }", "rows(8, \"k2, p2\")", render::RenderOptions::Side::face);
  const Image plied = preview("{ diameter = 1, section = \"plied\", plies = 3 }", kJersey8, render::RenderOptions::Side::face);
  EXPECT_GT(difference(jersey, rib), 2.0);
  EXPECT_GT(difference(jersey, plied), 1.0);
}

}  // namespace
}  // namespace knitc
