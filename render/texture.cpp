#include "texture.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace knitc::render {

glm::vec3 texel(const mesh::Image& image, glm::vec2 st) {
  assert(image.width > 0 && image.height > 0 && (image.channels == 1 || image.channels == 3));
  const float x = (st.x - std::floor(st.x)) * static_cast<float>(image.width) - 0.5f;
  const float y = (st.y - std::floor(st.y)) * static_cast<float>(image.height) - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  const float ax = x - fx, ay = y - fy;
  const auto wrap = [](int i, int n) { return ((i % n) + n) % n; };
  const int x0 = wrap(static_cast<int>(fx), image.width), x1 = wrap(x0 + 1, image.width);
  const int y0 = wrap(static_cast<int>(fy), image.height), y1 = wrap(y0 + 1, image.height);
  const auto at = [&](int i, int j) {
    const std::size_t p = (static_cast<std::size_t>(j) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(i)) *
                          static_cast<std::size_t>(image.channels);
    if (image.channels == 1) return glm::vec3(image.pixels[p]);
    return glm::vec3(image.pixels[p], image.pixels[p + 1], image.pixels[p + 2]);
  };
  const glm::vec3 top = (1.0f - ax) * at(x0, y0) + ax * at(x1, y0);
  const glm::vec3 bottom = (1.0f - ax) * at(x0, y1) + ax * at(x1, y1);
  return ((1.0f - ay) * top + ay * bottom) / 255.0f;
}

glm::vec3 linear_from_srgb(glm::vec3 srgb) {
  for (int c = 0; c < 3; ++c) {
    const float s = std::clamp(srgb[c], 0.0f, 1.0f);
    srgb[c] = s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
  }
  return srgb;
}

}  // namespace knitc::render
