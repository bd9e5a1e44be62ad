#include "image.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

// Debian's libstb-dev ships the implementation in libstb (pkg-config stb), so no
// STB_IMAGE_WRITE_IMPLEMENTATION here.
#include <stb/stb_image_write.h>

namespace knitc::render::detail {

namespace {

float srgb_encode(float linear) {
  const float c = linear <= 0.0f ? 0.0f : linear >= 1.0f ? 1.0f : linear;
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

// 16-bit linear to 8-bit sRGB, the whole range at once.
const std::array<std::uint8_t, 65536>& srgb_table() {
  static const auto table = [] {
    std::array<std::uint8_t, 65536> t{};
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = srgb8(static_cast<float>(i) / 65535.0f);
    return t;
  }();
  return table;
}

void append_bytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

}  // namespace

std::uint8_t srgb8(float linear) {
  return static_cast<std::uint8_t>(std::lround(255.0f * srgb_encode(linear)));
}

void resolve(const std::vector<std::uint16_t>& frame, int width, int height, int k, Image& out, int x0) {
  const auto& table = srgb_table();
  const auto w = static_cast<std::size_t>(width), kk = static_cast<std::size_t>(k);
  const std::size_t frame_width = w * kk;
  const std::uint64_t count = kk * kk;
  for (int y = 0; y < height; ++y) {
    // Output row y, counted from the top, comes from frame rows counted from the bottom.
    const auto first_row = static_cast<std::size_t>(height - 1 - y) * kk;
    std::uint8_t* dst = out.rgb.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(out.width) +
                                          static_cast<std::size_t>(x0)) * 3;
    for (std::size_t x = 0; x < w; ++x) {
      std::uint64_t sum[3] = {0, 0, 0};
      for (std::size_t r = first_row; r < first_row + kk; ++r) {
        const std::uint16_t* src = frame.data() + (r * frame_width + x * kk) * 4;
        for (std::size_t s = 0; s < kk; ++s, src += 4) {
          sum[0] += src[0];
          sum[1] += src[1];
          sum[2] += src[2];
        }
      }
      for (int c = 0; c < 3; ++c) *dst++ = table[(sum[c] + count / 2) / count];
    }
  }
}

std::string encode_png(const Image& image) {
  std::string bytes;
  if (!stbi_write_png_to_func(append_bytes, &bytes, image.width, image.height, 3, image.rgb.data(),
                              image.width * 3))
    throw std::runtime_error("render: cannot encode the PNG");
  return bytes;
}

}  // namespace knitc::render::detail
