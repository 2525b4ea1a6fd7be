#include "render/video_library.hpp"

#include <dlfcn.h>

#include <atomic>
#include <cstdarg>
#include <cstdlib>
#include <stdexcept>

namespace elbowsim {

namespace {

#define ELBOWSIM_STRINGIFY_(x) #x
#define ELBOWSIM_STRINGIFY(x) ELBOWSIM_STRINGIFY_(x)

// Debian's libavformat59 installs libavformat.so.59 (and the libavcodec and
// libavutil of the same FFmpeg as its dependencies).
constexpr const char* kLibavformat =
    "libavformat.so." ELBOWSIM_STRINGIFY(LIBAVFORMAT_VERSION_MAJOR);
constexpr const char* kDebianPackage = "libavformat" ELBOWSIM_STRINGIFY(LIBAVFORMAT_VERSION_MAJOR);

// Each thread's error messages from the libraries (an encoder runs on one thread).
thread_local std::string t_log;
constexpr std::size_t kLogLimit = 2000;

void keep_errors(void* context, int level, const char* format, va_list arguments);
// av_log_format_line, for keep_errors (set before it is installed).
std::atomic<decltype(&av_log_format_line)> format_line{nullptr};

template <class F>
void find(void* library, F& f, const char* name) {
  f = reinterpret_cast<F>(dlsym(library, name));
  if (!f)
    throw std::runtime_error(libavformat_file() + " (or its libavcodec, libavutil) has no " + name);
}

void check_version(void* library, const char* name, unsigned built_with) {
  unsigned (*version)() = nullptr;
  find(library, version, name);
  const unsigned major = AV_VERSION_MAJOR(version());
  if (major != built_with)
    throw std::runtime_error(libavformat_file() + ": " + name + " gives major version " +
                             std::to_string(major) + ", elbowsim was built for " +
                             std::to_string(built_with) + " (FFmpeg's structures differ)");
}

VideoLibrary open_video_library() {
  const std::string file = libavformat_file();
  void* library = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!library) {
    const char* error = dlerror();
    throw std::runtime_error("cannot load FFmpeg's " + file +
                             ", which encodes videos (Debian: apt-get install " + kDebianPackage +
                             "): " + (error ? error : "not found"));
  }
  // dlsym on libavformat's handle searches its dependencies too. The
  // structures are used as the headers lay them out: the major versions
  // (FFmpeg's ABI) must be the ones the program was built with.
  check_version(library, "avformat_version", LIBAVFORMAT_VERSION_MAJOR);
  check_version(library, "avcodec_version", LIBAVCODEC_VERSION_MAJOR);
  check_version(library, "avutil_version", LIBAVUTIL_VERSION_MAJOR);
  VideoLibrary v;
  find(library, v.strerror, "av_strerror");
  find(library, v.dict_set, "av_dict_set");
  find(library, v.dict_free, "av_dict_free");
  find(library, v.frame_alloc, "av_frame_alloc");
  find(library, v.frame_free, "av_frame_free");
  find(library, v.frame_unref, "av_frame_unref");
  find(library, v.buffer_pool_init, "av_buffer_pool_init");
  find(library, v.buffer_pool_get, "av_buffer_pool_get");
  find(library, v.buffer_pool_uninit, "av_buffer_pool_uninit");
  find(library, v.buffer_ref, "av_buffer_ref");
  find(library, v.buffer_unref, "av_buffer_unref");
  find(library, v.d2q, "av_d2q");
  find(library, v.log_set_callback, "av_log_set_callback");
  find(library, v.log_format_line, "av_log_format_line");
  find(library, v.find_encoder_by_name, "avcodec_find_encoder_by_name");
  find(library, v.alloc_context3, "avcodec_alloc_context3");
  find(library, v.free_context, "avcodec_free_context");
  find(library, v.open2, "avcodec_open2");
  find(library, v.parameters_from_context, "avcodec_parameters_from_context");
  find(library, v.send_frame, "avcodec_send_frame");
  find(library, v.receive_packet, "avcodec_receive_packet");
  find(library, v.packet_alloc, "av_packet_alloc");
  find(library, v.packet_free, "av_packet_free");
  find(library, v.packet_rescale_ts, "av_packet_rescale_ts");
  find(library, v.alloc_output_context2, "avformat_alloc_output_context2");
  find(library, v.free_format_context, "avformat_free_context");
  find(library, v.new_stream, "avformat_new_stream");
  find(library, v.io_open, "avio_open");
  find(library, v.io_closep, "avio_closep");
  find(library, v.write_header, "avformat_write_header");
  find(library, v.interleaved_write_frame, "av_interleaved_write_frame");
  find(library, v.write_trailer, "av_write_trailer");
  // Their messages go to the failing call's error, not to stderr: a video
  // that fails says why once, and one that works says nothing.
  format_line = v.log_format_line;
  v.log_set_callback(keep_errors);
  return v;
}

void keep_errors(void* context, int level, const char* format, va_list arguments) {
  if (level > AV_LOG_ERROR) return;
  char line[1024];
  int print_prefix = 1;
  format_line.load()(context, level, format, arguments, line, sizeof line, &print_prefix);
  t_log += line;
  if (t_log.size() > kLogLimit) t_log.erase(0, t_log.size() - kLogLimit);
}

}  // namespace

std::string libavformat_file() {
  const char* file = std::getenv("ELBOWSIM_LIBAVFORMAT");
  return file && *file ? file : kLibavformat;
}

// Loaded once, by whichever thread opens the first video; kept for the life
// of the process. A failed load is tried again by the next caller.
const VideoLibrary& video_library() {
  static const VideoLibrary library = open_video_library();
  return library;
}

std::string take_video_log() {
  std::string log;
  log.swap(t_log);
  return log;
}

}  // namespace elbowsim
