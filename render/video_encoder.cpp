#include "render/video_encoder.hpp"

#include <sys/prctl.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "engine/recording/number_text.hpp"
#include "render/video_library.hpp"
#include "render/yuv.hpp"

namespace elbowsim {

namespace {

// x264's settings, the same as the ffmpeg command's below.
const char* const kPreset = "veryfast";  // x264 speed/size trade-off; crf 20 looks clean
// Whole-pixel motion vectors (subme=0; veryfast refines them to quarter
// pixels, subme=2) and 4x4 transforms only (no-8x8dct). On the experiment's
// videos, measured against subme=1 (x264 alone, one thread): 8-15 % less
// encoding CPU for 2-5 % more bytes at the same PSNR and SSIM (48.7 dB,
// 0.9975). The 8x8 transform lost on this flat-shaded content: without it
// the videos were smaller and 0.07-0.1 dB better. (subme=1 against veryfast's
// 2: 22 % less CPU for 8 % more bytes; superfast: 2.3 times the bytes.)
const char* const kX264Params = "subme=0:no-8x8dct=1";
const char* const kCrf = "20";
// The colour matrix, primaries, transfer and range the video's header names
// (those rgba_to_yuv420 converts with; sRGB shares BT.709's primaries).
const char* const kColour[] = {"-colorspace", "bt709", "-color_primaries", "bt709",
                               "-color_trc",  "bt709", "-color_range",     "tv"};

// A failed call's reason: the library's text for `code`, then what it logged.
std::string reason(const VideoLibrary& av, int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av.strerror(code, text, sizeof text);
  std::string log = take_video_log();
  while (!log.empty() && log.back() == '\n') log.pop_back();
  return std::string(text) + (log.empty() ? "" : ":\n" + log);
}

// x264 asks the kernel for transparent huge pages for its pictures
// (madvise), and the kernel then clears, and with Debian's default "defrag:
// madvise" may first compact, 2 MiB at a time on first touch. With them
// off for this process the main job's system CPU fell from 0.62 to 0.21 s
// and its total CPU by 5 % (median of 6 in turns), its user CPU the same.
// Process-wide (Linux keeps it per process), and only x264 asks for huge
// pages here. Failing to turn them off costs only that time.
void no_huge_pages_for_pictures() { prctl(PR_SET_THP_DISABLE, 1, 0, 0, 0); }

}  // namespace

std::string video_unavailable() {
  try {
    const VideoLibrary& av = video_library();
    if (!av.find_encoder_by_name("libx264"))
      return "FFmpeg's " + libavformat_file() + " was built without libx264, the H.264 encoder";
    return "";
  } catch (const std::exception& e) {
    return e.what();
  }
}

std::string frames_to_video_command(const std::filesystem::path& frames,
                                    const std::filesystem::path& video, double fps) {
  std::string colour;
  for (const char* a : kColour) colour += std::string(" ") + a;
  return "ffmpeg -framerate " + significant(fps) + " -i '" + (frames / "frame_%05d.png").string() +
         "' -c:v libx264 -preset " + kPreset + " -x264-params " + kX264Params + " -crf " + kCrf +
         " -vf scale=out_color_matrix=bt709:out_range=tv -pix_fmt yuv420p" + colour +
         " -movflags +faststart '" + video.string() + "'";
}

// What is open, freed in reverse.
struct VideoEncoder::Codec {
  const VideoLibrary& av;
  AVCodecContext* context = nullptr;
  AVFormatContext* format = nullptr;
  AVStream* stream = nullptr;
  AVBufferPool* pool = nullptr;  // frames' YUV, reused once the encoder has copied them
  AVBufferRef* next = nullptr;   // the next frame's YUV, being filled
  AVBufferRef* last = nullptr;   // the last frame's YUV (yuv())
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  std::int64_t next_pts = 0;

  explicit Codec(const VideoLibrary& library) : av(library) {}
  ~Codec() {
    av.packet_free(&packet);
    av.frame_free(&frame);
    av.buffer_unref(&last);
    av.buffer_unref(&next);
    av.buffer_pool_uninit(&pool);
    av.free_context(&context);
    if (format) {
      if (format->pb) av.io_closep(&format->pb);
      av.free_format_context(format);
    }
  }
  Codec(const Codec&) = delete;
  Codec& operator=(const Codec&) = delete;

  [[noreturn]] void fail(const std::string& what, int code) const {
    throw std::runtime_error(what + ": " + reason(av, code));
  }
  // Writes the packets the encoder has ready; true once it has no more (end of stream).
  bool write_packets() {
    for (;;) {
      int status = av.receive_packet(context, packet);
      if (status == AVERROR(EAGAIN)) return false;
      if (status == AVERROR_EOF) return true;
      if (status < 0) fail("the H.264 encoder failed", status);
      av.packet_rescale_ts(packet, context->time_base, stream->time_base);
      packet->stream_index = stream->index;
      if ((status = av.interleaved_write_frame(format, packet)) < 0)
        fail("cannot write " + std::string(format->url), status);
    }
  }
};

namespace {

// x264's options: the settings above, or lossless (quantiser 0).
AVDictionary* encoder_options(const VideoLibrary& av, bool lossless) {
  AVDictionary* options = nullptr;
  av.dict_set(&options, "preset", kPreset, 0);
  av.dict_set(&options, "x264-params", kX264Params, 0);
  if (lossless)
    av.dict_set(&options, "qp", "0", 0);
  else
    av.dict_set(&options, "crf", kCrf, 0);
  return options;
}

}  // namespace

VideoEncoder::VideoEncoder(const std::filesystem::path& output, int width, int height, double fps,
                           bool lossless)
    : output_(output), width_(width), height_(height) {
  if (width <= 0 || height <= 0 || width % 2 || height % 2)
    throw std::invalid_argument("video: width and height must be even and positive");
  try {
    open(fps, lossless);
  } catch (...) {
    discard();
    throw;
  }
}

void VideoEncoder::open(double fps, bool lossless) {
  const std::filesystem::path& output = output_;
  const int width = width_, height = height_;
  const VideoLibrary& av = video_library();
  take_video_log();
  no_huge_pages_for_pictures();
  codec_ = std::make_unique<Codec>(av);
  Codec& c = *codec_;
  const AVCodec* x264 = av.find_encoder_by_name("libx264");
  if (!x264) throw std::runtime_error(video_unavailable());
  if (!(c.context = av.alloc_context3(x264))) throw std::bad_alloc();
  AVCodecContext& e = *c.context;
  e.width = width;
  e.height = height;
  e.pix_fmt = AV_PIX_FMT_YUV420P;
  e.framerate = av.d2q(fps, 1001000);
  e.time_base = AVRational{e.framerate.den, e.framerate.num};
  e.colorspace = AVCOL_SPC_BT709;
  e.color_primaries = AVCOL_PRI_BT709;
  e.color_trc = AVCOL_TRC_BT709;
  e.color_range = AVCOL_RANGE_MPEG;
  // x264 picks its thread count from the cores, and its bitstream depends on
  // it: one thread keeps the mp4 the same bytes on every machine. It keeps up
  // with drawing (over 200 frames/s at 1280 x 720), and a render's drawing
  // and writer threads already share the cores.
  e.thread_count = 1;
  int status = av.alloc_output_context2(&c.format, nullptr, "mp4", output.c_str());
  if (status < 0) c.fail("cannot make an mp4", status);
  if (c.format->oformat->flags & AVFMT_GLOBALHEADER) e.flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  AVDictionary* options = encoder_options(av, lossless);
  status = av.open2(c.context, x264, &options);
  av.dict_free(&options);
  if (status < 0) c.fail("cannot start the H.264 encoder", status);
  if (!(c.stream = av.new_stream(c.format, nullptr))) throw std::bad_alloc();
  if ((status = av.parameters_from_context(c.stream->codecpar, c.context)) < 0)
    c.fail("cannot describe the video stream", status);
  c.stream->time_base = e.time_base;
  c.stream->avg_frame_rate = e.framerate;
  if ((status = av.io_open(&c.format->pb, output.c_str(), AVIO_FLAG_WRITE)) < 0)
    c.fail("cannot write " + output.string(), status);
  // The index first, so that a browser plays the video while it loads.
  AVDictionary* muxer = nullptr;
  av.dict_set(&muxer, "movflags", "+faststart", 0);
  status = av.write_header(c.format, &muxer);
  av.dict_free(&muxer);
  if (status < 0) c.fail("cannot write " + output.string(), status);
  if (!(c.pool = av.buffer_pool_init(yuv420_bytes(width, height), nullptr))) throw std::bad_alloc();
  if (!(c.frame = av.frame_alloc()) || !(c.packet = av.packet_alloc())) throw std::bad_alloc();
}

VideoEncoder::~VideoEncoder() { discard(); }

void VideoEncoder::discard() {
  const bool opened = codec_ && codec_->format && codec_->format->pb;
  codec_.reset();
  std::error_code ignored;
  if (opened) std::filesystem::remove(output_, ignored);  // only a file this made
}

std::uint8_t* VideoEncoder::next_yuv() {
  Codec& c = *codec_;
  if (!c.next && !(c.next = c.av.buffer_pool_get(c.pool))) throw std::bad_alloc();
  return c.next->data;
}

void VideoEncoder::encode_next_yuv() {
  Codec& c = *codec_;
  next_yuv();
  c.av.buffer_unref(&c.last);
  c.last = std::exchange(c.next, nullptr);
  AVFrame& f = *c.frame;
  // The frame refers to the pool's buffer: x264 copies it into its own
  // pictures, so no copy is made here, and the buffer returns to the pool
  // when neither the encoder nor `last` holds it.
  if (!(f.buf[0] = c.av.buffer_ref(c.last))) throw std::bad_alloc();
  const std::size_t luma = std::size_t(width_) * std::size_t(height_);
  f.data[0] = c.last->data;
  f.data[1] = f.data[0] + luma;
  f.data[2] = f.data[1] + luma / 4;
  f.linesize[0] = width_;
  f.linesize[1] = f.linesize[2] = width_ / 2;
  f.width = width_;
  f.height = height_;
  f.format = AV_PIX_FMT_YUV420P;
  f.pts = c.next_pts++;
  const int status = c.av.send_frame(c.context, &f);
  c.av.frame_unref(&f);
  if (status < 0) c.fail("the H.264 encoder failed", status);
  c.write_packets();
}

void VideoEncoder::write(ConstRgbaView frame) {
  if (frame.width != width_ || frame.height != height_)
    throw std::invalid_argument("video: a frame of another size than the video's");
  rgba_to_yuv420(frame, next_yuv());
  encode_next_yuv();
}

const std::uint8_t* VideoEncoder::yuv() const {
  return codec_ && codec_->last ? codec_->last->data : nullptr;
}

void VideoEncoder::finish() {
  Codec& c = *codec_;
  int status = c.av.send_frame(c.context, nullptr);  // the end: x264 gives what it held back
  if (status < 0) c.fail("the H.264 encoder failed", status);
  if (!c.write_packets())
    throw std::runtime_error("the H.264 encoder did not finish " + output_.string());
  if ((status = c.av.write_trailer(c.format)) < 0)
    c.fail("cannot write " + output_.string(), status);
  status = c.av.io_closep(&c.format->pb);
  if (status < 0) {  // closed anyway: the file goes here
    const std::string why = reason(c.av, status);
    codec_.reset();
    std::error_code ignored;
    std::filesystem::remove(output_, ignored);
    throw std::runtime_error("cannot write " + output_.string() + ": " + why);
  }
  codec_.reset();
}

}  // namespace elbowsim
