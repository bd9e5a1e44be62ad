// From the supersampled frame OpenGL drew to the PNG file: averaging, sRGB encoding, rows.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace knitc::render::detail {

// An 8-bit sRGB RGB image, rows top-down.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3
};

// Averages each k x k block of `frame` (RGBA, 16 bits a channel, linear light, (width * k) x
// (height * k) pixels, rows bottom-up) into one pixel, encodes it as sRGB and writes it into
// `out` at column x0, turning the rows top-down. `out` must be at least x0 + width wide and
// height tall.
void resolve(const std::vector<std::uint16_t>& frame, int width, int height, int k, Image& out, int x0);

// The linear value in [0, 1] as an 8-bit sRGB code, rounded to nearest.
std::uint8_t srgb8(float linear);

// The bytes of a PNG file of the image. Throws std::runtime_error if encoding fails.
std::string encode_png(const Image& image);

}  // namespace knitc::render::detail
