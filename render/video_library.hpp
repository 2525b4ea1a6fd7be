// FFmpeg's libraries, for video: libavcodec (its libx264 encoder),
// libavformat (the mp4 muxer) and libavutil, used in-process and loaded with
// dlopen on the first video. In-process, the frames go to x264 without the
// pipe, the ffmpeg process and its start-up (7 % of the main job's CPU);
// loaded late, a start that makes no video does not pay for libavformat and
// its hundred dependencies (20 ms). Their headers give the types only.
#pragma once

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include <string>

namespace elbowsim {

// The entry points used, looked up in libavformat and the libraries it
// depends on (libavcodec, libavutil) for the versions the program was built
// with.
struct VideoLibrary {
  // libavutil
  decltype(&av_strerror) strerror = nullptr;
  decltype(&av_dict_set) dict_set = nullptr;
  decltype(&av_dict_free) dict_free = nullptr;
  decltype(&av_frame_alloc) frame_alloc = nullptr;
  decltype(&av_frame_free) frame_free = nullptr;
  decltype(&av_frame_unref) frame_unref = nullptr;
  decltype(&av_buffer_pool_init) buffer_pool_init = nullptr;
  decltype(&av_buffer_pool_get) buffer_pool_get = nullptr;
  decltype(&av_buffer_pool_uninit) buffer_pool_uninit = nullptr;
  decltype(&av_buffer_ref) buffer_ref = nullptr;
  decltype(&av_buffer_unref) buffer_unref = nullptr;
  decltype(&av_d2q) d2q = nullptr;
  decltype(&av_log_set_callback) log_set_callback = nullptr;
  decltype(&av_log_format_line) log_format_line = nullptr;
  // libavcodec
  decltype(&avcodec_find_encoder_by_name) find_encoder_by_name = nullptr;
  decltype(&avcodec_alloc_context3) alloc_context3 = nullptr;
  decltype(&avcodec_free_context) free_context = nullptr;
  decltype(&avcodec_open2) open2 = nullptr;
  decltype(&avcodec_parameters_from_context) parameters_from_context = nullptr;
  decltype(&avcodec_send_frame) send_frame = nullptr;
  decltype(&avcodec_receive_packet) receive_packet = nullptr;
  decltype(&av_packet_alloc) packet_alloc = nullptr;
  decltype(&av_packet_free) packet_free = nullptr;
  decltype(&av_packet_rescale_ts) packet_rescale_ts = nullptr;
  // libavformat
  decltype(&avformat_alloc_output_context2) alloc_output_context2 = nullptr;
  decltype(&avformat_free_context) free_format_context = nullptr;
  decltype(&avformat_new_stream) new_stream = nullptr;
  decltype(&avio_open) io_open = nullptr;
  decltype(&avio_closep) io_closep = nullptr;
  decltype(&avformat_write_header) write_header = nullptr;
  decltype(&av_interleaved_write_frame) interleaved_write_frame = nullptr;
  decltype(&av_write_trailer) write_trailer = nullptr;
};

// The libavformat file to load: $ELBOWSIM_LIBAVFORMAT if set (a library
// elsewhere), else libavformat.so.N for the N the program was built with.
std::string libavformat_file();

// The loaded library (the first call loads it, and installs a log callback
// that keeps each thread's error messages for take_video_log), or throws
// std::runtime_error saying what could not be loaded and what to install.
const VideoLibrary& video_library();

// What the libraries logged at error level on this thread since the last
// call (at most about 2000 characters, the latest kept); then cleared.
std::string take_video_log();

}  // namespace elbowsim
