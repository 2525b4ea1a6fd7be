// A report all or nothing. A report writes <folder>/plots/ and then
// <folder>/report.html (html::write_file: renamed into place at the end).
// PlotsAside, made before the first plot, moves an earlier plots/ aside
// (plots.old); if the report then fails (an exception leaves its scope
// before keep()), the new plots go and the earlier ones come back, so the
// folder keeps the earlier report whole instead of half of a new one.
#pragma once

#include <filesystem>

namespace elbowsim::report {

class PlotsAside {
 public:
  // A plots.old left by a process that died mid-report holds the last
  // complete plots: it is put back first.
  explicit PlotsAside(std::filesystem::path folder);
  ~PlotsAside();
  PlotsAside(const PlotsAside&) = delete;
  PlotsAside& operator=(const PlotsAside&) = delete;

  // The report is written: the earlier plots go.
  void keep();

 private:
  std::filesystem::path plots_, aside_;
  bool moved_ = false, kept_ = false;
};

}  // namespace elbowsim::report
