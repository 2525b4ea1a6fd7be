#include "render/video_encoder.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "render/yuv.hpp"

extern char** environ;

namespace elbowsim {

namespace {

std::string format_fps(double fps) {
  std::ostringstream s;
  s << fps;
  return s.str();
}

// ffmpeg's options in its own order: input (raw YUV on stdin), then output.
const char* const kPreset = "veryfast";  // x264 speed/size trade-off; crf 20 looks clean
// Sub-pixel motion refinement 1 instead of veryfast's 2 (superfast's): on
// the experiment's video 22 % less encoding CPU for 8 % more bytes, PSNR
// 50.8 instead of 51.3 dB (superfast: 20 % less CPU, 2.3 times the bytes).
const char* const kX264Params = "subme=1";
const char* const kCrf = "20";
const char* const kEncoderThreads = "1";  // see ffmpeg_arguments
// The colour matrix, primaries, transfer and range the video's header names
// (those rgb_to_yuv420 converts with; sRGB shares BT.709's primaries).
const char* const kColour[] = {"-colorspace", "bt709", "-color_primaries", "bt709",
                               "-color_trc",  "bt709", "-color_range",     "tv"};

}  // namespace

std::filesystem::path find_on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return {};
  std::stringstream dirs(path);
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const std::filesystem::path candidate =
        std::filesystem::path(dir.empty() ? "." : dir) / program;
    struct stat st;
    if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
        ::access(candidate.c_str(), X_OK) == 0)
      return candidate;
  }
  return {};
}

std::vector<std::string> ffmpeg_arguments(const std::filesystem::path& output, int width,
                                          int height, double fps) {
  std::vector<std::string> args = {"-hide_banner", "-loglevel", "error", "-y", "-f", "rawvideo",
                                   "-pix_fmt", "yuv420p", "-video_size",
                                   std::to_string(width) + "x" + std::to_string(height),
                                   "-framerate", format_fps(fps)};
  args.insert(args.end(), std::begin(kColour), std::end(kColour));
  // x264 picks its thread count from the cores, and its bitstream depends on
  // it: a fixed count keeps the mp4 the same bytes on every machine. One:
  // the encoder keeps up with drawing (over 200 frames/s at 1280 x 720),
  // a render's encoders and drawing threads already share the cores, and a
  // second thread costs 5-10 % more CPU in hand-offs and frames in flight.
  for (const char* a :
       {"-i", "pipe:0", "-an", "-c:v", "libx264", "-preset", kPreset, "-x264-params", kX264Params,
        "-crf", kCrf, "-threads", kEncoderThreads, "-pix_fmt", "yuv420p"})
    args.emplace_back(a);
  args.insert(args.end(), std::begin(kColour), std::end(kColour));
  for (const char* a : {"-movflags", "+faststart", "-f", "mp4"}) args.emplace_back(a);
  args.push_back(output.string());
  return args;
}

std::string frames_to_video_command(const std::filesystem::path& frames,
                                    const std::filesystem::path& video, double fps) {
  std::string colour;
  for (const char* a : kColour) colour += std::string(" ") + a;
  return "ffmpeg -framerate " + format_fps(fps) + " -i '" + (frames / "frame_%05d.png").string() +
         "' -c:v libx264 -preset " + kPreset + " -x264-params " + kX264Params + " -crf " + kCrf +
         " -vf scale=out_color_matrix=bt709:out_range=tv -pix_fmt yuv420p" + colour +
         " -movflags +faststart '" + video.string() + "'";
}

VideoEncoder::VideoEncoder(const std::filesystem::path& ffmpeg, const std::filesystem::path& output,
                           int width, int height, double fps)
    : output_(output),
      log_(output.string() + ".log"),
      width_(width),
      height_(height),
      yuv_(yuv420_bytes(width, height)) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0)
    throw std::runtime_error(std::string("cannot make a pipe to ffmpeg: ") + std::strerror(errno));
  // The child: stdin from the pipe, stdout to /dev/null, stderr to the log.
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, log_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> args = ffmpeg_arguments(output, width, height, fps);
  args.insert(args.begin(), ffmpeg.string());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const int error = ::posix_spawn(&pid_, ffmpeg.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[0]);
  if (error != 0) {
    ::close(fds[1]);
    std::filesystem::remove(log_);
    throw std::runtime_error("cannot start " + ffmpeg.string() + ": " + std::strerror(error));
  }
  pipe_ = fds[1];
  // A write to a pipe ffmpeg has closed must fail with EPIPE, not kill us.
  old_sigpipe_ = std::signal(SIGPIPE, SIG_IGN);
}

VideoEncoder::~VideoEncoder() {
  if (pid_ > 0) {
    ::kill(pid_, SIGTERM);
    stop();
    std::error_code ignored;
    std::filesystem::remove(output_, ignored);
    std::filesystem::remove(log_, ignored);
  }
  if (old_sigpipe_ != nullptr) std::signal(SIGPIPE, old_sigpipe_);
}

void VideoEncoder::write(const std::uint8_t* rgb) {
  rgb_to_yuv420(rgb, width_, height_, yuv_.data());
  write_yuv(yuv_.data());
}

void VideoEncoder::write_yuv(const std::uint8_t* yuv) {
  std::size_t done = 0;
  while (done < yuv_.size()) {
    const ssize_t n = ::write(pipe_, yuv + done, yuv_.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error("ffmpeg stopped reading frames" + log_tail());
    done += std::size_t(n);
  }
}

int VideoEncoder::stop() {
  if (pipe_ >= 0) ::close(pipe_);
  pipe_ = -1;
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  return status;
}

void VideoEncoder::finish() {
  const int status = stop();
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    std::filesystem::remove(log_);
    return;
  }
  const std::string messages = log_tail();
  std::error_code ignored;
  std::filesystem::remove(output_, ignored);
  std::filesystem::remove(log_, ignored);
  throw std::runtime_error("ffmpeg failed (wait status " + std::to_string(status) + ")" + messages);
}

std::string VideoEncoder::log_tail() const {
  std::ifstream in(log_);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (text.size() > 2000) text = "..." + text.substr(text.size() - 2000);
  return text.empty() ? std::string() : ":\n" + text;
}

}  // namespace elbowsim
