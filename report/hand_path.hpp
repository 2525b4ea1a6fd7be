// The hand's path in its task plane, desired against actual: the figure a
// tracking error is read from. Errors of micrometres vanish on a path of
// centimetres, so a second view draws desired + k·(actual − desired) with a
// stated magnification k. Planar arms move in x–z (docs/conventions.md);
// for others the coordinate plane in which the hand's path is largest.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "report/plot/plot.hpp"
#include "report/run_data.hpp"

namespace elbowsim::report {

struct TaskPlane {
  int a = 0, b = 2;  // horizontal and vertical axis: 0, 1, 2 = x, y, z
  std::string name;  // "x–z"
  std::string why;   // "the arm is planar (hand_y is 0 throughout)", ...
};

// The plane of the runs' hand paths (all recordings must have samples).
TaskPlane task_plane(const std::vector<const Recording*>& recordings);

// 1, 2 or 5 x 10^n, so that the largest in-plane error of the runs, times k,
// is at most a tenth of the path's extent; 1 when the errors already show (or
// there is no desired path).
double error_magnification(const std::vector<const Recording*>& recordings, const TaskPlane& plane);

struct HandPathFigures {
  plot::LinePlot path;                      // desired (dashed) and actual, equal scales
  std::optional<plot::LinePlot> magnified;  // desired and desired + k·error; none without a task
  double k = 1;
  std::string path_caption, magnified_caption;
};

// The figures of one run or of several (colours by run, one desired path
// when they share it). `title_suffix` names the run(s): "elbow_experiment · elbow_on".
HandPathFigures hand_path_figures(const std::vector<const RunData*>& runs,
                                  const std::string& title_suffix);

}  // namespace elbowsim::report
