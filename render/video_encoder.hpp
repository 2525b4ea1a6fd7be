// Video through the `ffmpeg` program: frames are converted to YUV 4:2:0
// (BT.709, limited range: render/yuv.hpp) and piped raw to its stdin; it
// writes H.264 (libx264), yuv420p, tagged BT.709, in an .mp4 with +faststart.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace elbowsim {

// The first executable file named `program` in the PATH directories; empty if none.
std::filesystem::path find_on_path(const std::string& program);

// The arguments ffmpeg gets (after the program name) to encode raw YUV 4:2:0
// frames from stdin into `output`.
std::vector<std::string> ffmpeg_arguments(const std::filesystem::path& output, int width,
                                          int height, double fps);

// The command that turns PNG frames frame_00001.png ... into the same video,
// for when ffmpeg was not available during the render.
std::string frames_to_video_command(const std::filesystem::path& frames,
                                    const std::filesystem::path& video, double fps);

class VideoEncoder {
 public:
  // Starts `ffmpeg` (a path, e.g. from find_on_path) writing `output`
  // (width, height even). ffmpeg's messages go to <output>.log, removed when
  // the video is finished. Throws std::runtime_error if it cannot start.
  VideoEncoder(const std::filesystem::path& ffmpeg, const std::filesystem::path& output, int width,
               int height, double fps);
  // Without finish(): stops ffmpeg and removes what it wrote.
  ~VideoEncoder();
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  // One frame: width * height * 3 bytes, RGB, rows top-down (converted to
  // YUV in the calling thread). Throws if ffmpeg has stopped (its last
  // messages in what()).
  void write(const std::uint8_t* rgb);
  // One frame already in YUV 4:2:0 (yuv420_bytes(width, height) bytes, as rgb_to_yuv420 gives).
  void write_yuv(const std::uint8_t* yuv);
  // The last frame write() converted (its planes), for a side-by-side to reuse.
  const std::uint8_t* yuv() const { return yuv_.data(); }
  // Closes the pipe and waits for ffmpeg; throws with its messages if it failed.
  void finish();

 private:
  std::string log_tail() const;
  int stop();  // closes the pipe, reaps ffmpeg, returns its wait status

  std::filesystem::path output_, log_;
  int width_, height_;
  std::vector<std::uint8_t> yuv_;  // one frame, as piped
  int pipe_ = -1;  // write end, ffmpeg's stdin
  pid_t pid_ = -1;
  void (*old_sigpipe_)(int) = nullptr;
};

}  // namespace elbowsim
