#include "render/png_writer.hpp"

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

namespace elbowsim {

namespace {

struct File {
  std::FILE* f;
  ~File() {
    if (f) std::fclose(f);
  }
};

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw std::runtime_error(path.string() + ": " + what);
}

}  // namespace

std::string frame_file_name(int index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", index + 1);
  return name;
}

void write_png(const std::filesystem::path& path, ConstRgbaView frame) {
  File file{std::fopen(path.c_str(), "wb")};
  if (!file.f) fail(path, std::string("cannot write: ") + std::strerror(errno));
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    fail(path, "libpng could not start");
  }
  // libpng reports errors by longjmp: nothing with a destructor lives below.
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    fail(path, "libpng failed to write the image");
  }
  png_init_io(png, file.f);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_compression_level(png, 2);
  png_set_IHDR(png, info, png_uint_32(frame.width), png_uint_32(frame.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE,
               PNG_FILTER_TYPE_BASE);
  png_write_info(png, info);
  png_set_filler(png, 0, PNG_FILLER_AFTER);  // rows of 4 bytes a pixel, the 4th left out
  for (int y = 0; y < frame.height; ++y) png_write_row(png, const_cast<png_bytep>(frame.row(y)));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  if (std::fflush(file.f) != 0) fail(path, std::string("write failed: ") + std::strerror(errno));
}

std::vector<std::uint8_t> read_png(const std::filesystem::path& path, int& width, int& height) {
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) fail(path, image.message);
  image.format = PNG_FORMAT_RGB;
  std::vector<std::uint8_t> rgb(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, rgb.data(), 0, nullptr)) {
    png_image_free(&image);
    fail(path, image.message);
  }
  width = int(image.width);
  height = int(image.height);
  return rgb;
}

}  // namespace elbowsim
