#include "app/scenario/checks.hpp"

#include "engine/recording/number_text.hpp"

namespace elbowsim::loader {

double number(const Value& v) { return v.number(); }

double positive(const Value& v) {
  double x = v.number();
  if (!(x > 0)) v.fail("must be > 0 (got " + significant(x) + ")");
  return x;
}

double non_negative(const Value& v) {
  double x = v.number();
  if (!(x >= 0)) v.fail("must be >= 0 (got " + significant(x) + ")");
  return x;
}

Eigen::Vector3d vec3(const Value& v) { return v.vec3(); }

std::string text(const Value& v) { return v.text(); }

bool boolean(const Value& v) { return v.boolean(); }

Eigen::Matrix3d rpy_rotation(const Eigen::Vector3d& rpy) {
  using Eigen::AngleAxisd;
  using Eigen::Vector3d;
  return (AngleAxisd(rpy.z(), Vector3d::UnitZ()) * AngleAxisd(rpy.y(), Vector3d::UnitY()) *
          AngleAxisd(rpy.x(), Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Isometry3d pose(const Value& v) {
  v.allow_keys({"xyz", "rpy"});
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = rpy_rotation(value_or(v.get("rpy"), Eigen::Vector3d::Zero().eval(), vec3));
  out.translation() = value_or(v.get("xyz"), Eigen::Vector3d::Zero().eval(), vec3);
  return out;
}

Eigen::VectorXd per_joint(const Value& v, int dof) { return v.numbers(dof, "one per joint"); }

}  // namespace elbowsim::loader
