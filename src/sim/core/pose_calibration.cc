// pose_calibration.cc: see pose_calibration.h.
#include "sim/core/pose_calibration.h"

#include <cmath>
#include <cstdio>

#include <Eigen/Dense>

#include "base/format.h"
#include "base/input_error.h"
#include "base/units.h"
#include "sim/core/muscle_law.h"

namespace pamsim {
namespace {

constexpr int kMaxIterations = 50;
constexpr double kTorqueTolerance = 1e-9;  // N m
constexpr double kLengthStep = 1e-7;       // m, the pull's slope by central differences

// What the balance needs at the pose: each muscle's moment arms on the crossed joints.
struct Pose {
  std::vector<int> dofs;    // the dofs a muscle crosses
  Eigen::MatrixXd moments;  // dofs x muscles, r_ji
  Eigen::VectorXd needed;   // qfrc_passive - qfrc_bias on those dofs
};

Pose pose_of(const TrialModel& tm, const mjData* d, PoseCalibration* out) {
  const mjModel* m = tm.model.get();
  Pose pose;
  for (int j = 0; j < m->nv; ++j) {
    for (const BoundMuscle& b : tm.muscles) {
      if (std::fabs(d->actuator_moment[b.actuator * m->nv + j]) > 1e-12) {
        pose.dofs.push_back(j);
        const char* name = mj_id2name(m, mjOBJ_JOINT, m->dof_jntid[j]);
        out->joints.push_back(name ? name : "dof " + std::to_string(j));
        break;
      }
    }
  }
  const auto n = static_cast<Eigen::Index>(tm.muscles.size());
  const auto k = static_cast<Eigen::Index>(pose.dofs.size());
  pose.moments.resize(k, n);
  pose.needed.resize(k);
  for (Eigen::Index j = 0; j < k; ++j) {
    const int dof = pose.dofs[static_cast<std::size_t>(j)];
    pose.needed(j) = d->qfrc_passive[dof] - d->qfrc_bias[dof];
    for (Eigen::Index i = 0; i < n; ++i) {
      pose.moments(j, i) =
          d->actuator_moment[tm.muscles[static_cast<std::size_t>(i)].actuator * m->nv + dof];
    }
  }
  return pose;
}

// Pulls and their slopes dF/dd at the lines' deformations.
void pulls(const Scenario& sc, const TrialModel& tm, const PoseCalibration& c,
           Eigen::VectorXd* force, Eigen::VectorXd* slope) {
  for (std::size_t i = 0; i < c.lines.size(); ++i) {
    const MuscleSpec& spec = sc.muscles[tm.muscles[i].spec];
    const PoseLine& l = c.lines[i];
    const double length = l.free_length_m + l.deformation_m;
    const auto at = [&](double x) { return plant_static_force(spec, l.pressure_pa, x); };
    (*force)(static_cast<Eigen::Index>(i)) = at(length);
    (*slope)(static_cast<Eigen::Index>(i)) =
        (at(length + kLengthStep) - at(length - kLengthStep)) / (2 * kLengthStep);
  }
}

// Gauss-Newton toward sum r F(d) = needed, each step the one nearest the uniform d.
void balance(const Scenario& sc, const TrialModel& tm, const Pose& pose, double d0,
             PoseCalibration* c) {
  const auto n = static_cast<Eigen::Index>(c->lines.size());
  Eigen::VectorXd force(n), slope(n), d(n);
  for (Eigen::Index i = 0; i < n; ++i) d(i) = c->lines[static_cast<std::size_t>(i)].deformation_m;
  for (c->iterations = 1; c->iterations <= kMaxIterations; ++c->iterations) {
    pulls(sc, tm, *c, &force, &slope);
    const Eigen::VectorXd g = pose.moments * force - pose.needed;
    if (g.lpNorm<Eigen::Infinity>() < kTorqueTolerance) return;
    const Eigen::MatrixXd jac = pose.moments * slope.asDiagonal();
    // d_new = d0 - J^T (J J^T)^-1 (g + J (d0 - d)): the nearest point of the linearised set
    const Eigen::VectorXd d0_vec = Eigen::VectorXd::Constant(n, d0);
    const Eigen::VectorXd rhs = g + jac * (d0_vec - d);
    d = d0_vec - jac.transpose() * (jac * jac.transpose()).ldlt().solve(rhs);
    for (Eigen::Index i = 0; i < n; ++i) {
      if (!(d(i) > 0)) {
        throw InputError(
            "calibrate --pose --balance: the muscles cannot hold the pose with "
            "every line taut (" +
            c->lines[static_cast<std::size_t>(i)].muscle + " would be " +
            format_value(units::m_to_mm(d(i))) +
            " mm past its "
            "free length)");
      }
      c->lines[static_cast<std::size_t>(i)].deformation_m = d(i);
    }
  }
  throw InputError("calibrate --pose --balance: no balance within " +
                   std::to_string(kMaxIterations) + " iterations");
}

}  // namespace

PoseCalibration solve_pose_calibration(const TrialModel& tm, const Scenario& sc,
                                       const PoseCalibrationRequest& req) {
  if (!(req.deformation_m > 0)) {
    throw InputError("calibrate: --deformation-mm must be > 0, got " +
                     format_value(units::m_to_mm(req.deformation_m)));
  }
  if (!std::isfinite(req.pressure_pa)) throw InputError("calibrate: --pressure-MPa must be finite");
  const mjModel* m = tm.model.get();
  MjDataPtr data = make_data(m);
  tm.place_at_start(sc, data.get());
  mj_forward(m, data.get());
  PoseCalibration c;
  for (const BoundMuscle& b : tm.muscles) {
    const MuscleSpec& spec = sc.muscles[b.spec];
    PoseLine l;
    l.muscle = spec.key;
    l.tendon_m = data->actuator_length[b.actuator];
    l.pressure_pa = req.pressure_pa >= 0 ? req.pressure_pa : spec.command.at(0.0);
    l.free_length_m = plant_free_length(spec, l.pressure_pa);
    l.deformation_m = req.deformation_m;
    c.lines.push_back(l);
  }
  const Pose pose = pose_of(tm, data.get(), &c);
  if (req.balance) balance(sc, tm, pose, req.deformation_m, &c);
  const auto n = static_cast<Eigen::Index>(c.lines.size());
  Eigen::VectorXd force(n), slope(n);
  pulls(sc, tm, c, &force, &slope);
  const Eigen::VectorXd residual = pose.moments * force - pose.needed;
  c.residual_nm.assign(residual.data(), residual.data() + residual.size());
  for (std::size_t i = 0; i < c.lines.size(); ++i) {
    c.lines[i].force_n = force(static_cast<Eigen::Index>(i));
    if (!(c.lines[i].line_m() > 0)) {
      throw InputError(tm.model_path + ": " + c.lines[i].muscle +
                       "'s tendon is shorter than "
                       "its muscle at the pose; move its anchors apart");
    }
  }
  return c;
}

std::string pose_calibration_toml(const PoseCalibration& c, const std::string& header) {
  std::string out = header;
  char buf[200];
  for (const PoseLine& l : c.lines) {
    std::snprintf(buf, sizeof(buf),
                  "\n[%s]\nline_mm = %.4f   # tendon %.3f mm, %.3f mm past its free length "
                  "at %.3g MPa, pulling %.2f N\n",
                  l.muscle.c_str(), units::m_to_mm(l.line_m()), units::m_to_mm(l.tendon_m),
                  units::m_to_mm(l.deformation_m), units::pa_to_mpa(l.pressure_pa), l.force_n);
    out += buf;
  }
  return out;
}

}  // namespace pamsim
