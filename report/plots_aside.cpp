#include "report/plots_aside.hpp"

namespace elbowsim::report {

namespace fs = std::filesystem;

PlotsAside::PlotsAside(fs::path folder)
    : plots_(folder / "plots"), aside_(std::move(folder) / "plots.old") {
  if (fs::exists(aside_)) {
    fs::remove_all(plots_);
    fs::rename(aside_, plots_);
  }
  if (fs::exists(plots_)) {
    fs::rename(plots_, aside_);
    moved_ = true;
  }
}

PlotsAside::~PlotsAside() {
  if (kept_) return;
  std::error_code ignored;
  fs::remove_all(plots_, ignored);
  if (moved_) fs::rename(aside_, plots_, ignored);
}

void PlotsAside::keep() {
  kept_ = true;
  std::error_code ignored;
  if (moved_) fs::remove_all(aside_, ignored);
}

}  // namespace elbowsim::report
