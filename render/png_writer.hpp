// PNG files via libpng: the only file that includes png.h (docs/architecture.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "render/rgba_view.hpp"

namespace elbowsim {

// Writes a frame as an 8-bit RGB PNG (the fourth bytes are left out). Fast
// settings for frame sequences: the SUB filter only, zlib level 2. Throws
// std::runtime_error naming the file on failure.
void write_png(const std::filesystem::path& path, ConstRgbaView frame);

// The name of frame `index` (from 0) of a sequence: frame_00001.png, ...
std::string frame_file_name(int index);

// Reads an 8-bit RGB or RGBA PNG back as RGB (for tests). Throws on failure.
std::vector<std::uint8_t> read_png(const std::filesystem::path& path, int& width, int& height);

}  // namespace elbowsim
