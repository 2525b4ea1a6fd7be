// Video in-process with FFmpeg's libraries (render/video_library.hpp):
// frames converted to YUV 4:2:0 (BT.709, limited range: render/yuv.hpp),
// encoded H.264 by libx264 (preset veryfast, subme 0, no 8x8 DCT, crf 20, one thread, so
// the same bytes on every machine; or lossless), tagged BT.709, into an .mp4
// with its index first (+faststart), as the ffmpeg command below would.
// Opening one turns transparent huge pages off for the process (x264's
// pictures are cheaper on first touch without them: video_encoder.cpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "render/rgba_view.hpp"

namespace elbowsim {

// "" when videos can be made here, else why not (FFmpeg's libraries could
// not be loaded, or have no libx264): the caller writes frames instead.
std::string video_unavailable();

// The ffmpeg command that turns PNG frames frame_00001.png ... into the same
// video, for when no video could be made during the render.
std::string frames_to_video_command(const std::filesystem::path& frames,
                                    const std::filesystem::path& video, double fps);

class VideoEncoder {
 public:
  // Opens `output` for a width x height video (both even) at `fps` frames
  // per second; `lossless`: x264 at quantiser 0, whose frames decode to
  // exactly the YUV given (High 4:4:4 Predictive profile: for archives and
  // checks; browsers may not play it). Throws std::runtime_error with the
  // reason if the libraries are missing or the file cannot be opened.
  VideoEncoder(const std::filesystem::path& output, int width, int height, double fps,
               bool lossless = false);
  // Without finish(): closes and removes what it wrote.
  ~VideoEncoder();
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  // One frame of width x height (converted to YUV and encoded in the
  // calling thread). Throws if encoding or writing fails (the reason in what()).
  void write(ConstRgbaView frame);
  // The buffer the next frame's YUV 4:2:0 goes into (yuv420_bytes(width,
  // height), as rgba_to_yuv420 fills it; the same one until it is encoded), for a caller that
  // composes a frame in place; then encode_next_yuv() encodes it.
  std::uint8_t* next_yuv();
  void encode_next_yuv();
  // The last frame encoded (its planes), for a side-by-side to reuse; valid
  // until the next one is encoded.
  const std::uint8_t* yuv() const;
  // Encodes the frames still held back, writes the index; throws with the
  // reason if that fails (the destructor then removes the file).
  void finish();

 private:
  struct Codec;  // the libraries' state (video_encoder.cpp)
  void open(double fps, bool lossless);
  void discard();  // closes without finishing; removes the file if it was opened

  std::filesystem::path output_;
  int width_, height_;
  std::unique_ptr<Codec> codec_;
};

}  // namespace elbowsim
