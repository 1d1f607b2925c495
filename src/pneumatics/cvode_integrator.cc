// cvode_integrator.cc: CVODE 6.4 wrapper (see cvode_integrator.h).
#include "pneumatics/cvode_integrator.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sundials/sundials_version.h>
#include <sunmatrix/sunmatrix_band.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cstdlib>
#include <string>

namespace pamsim {
namespace {

// CVodeGetReturnFlagName allocates its result; copy and free it
std::string flag_name(int flag) {
  char* name = CVodeGetReturnFlagName(flag);
  std::string s = name != nullptr ? name : "unknown flag";
  std::free(name);
  return s;
}

}  // namespace

std::string sundials_version() {
  char version[64] = {};
  if (SUNDIALSGetVersion(version, static_cast<int>(sizeof(version))) != 0) return "unknown";
  return version;
}

CvodeIntegrator::CvodeIntegrator(OdeSystem& system, const CvodeOptions& options, double t0,
                                 const std::vector<double>& y0)
    : system_(system), size_(system.size()), t_(t0) {
  if (size_ <= 0 || static_cast<int>(y0.size()) != size_) {
    throw IntegrationError("CvodeIntegrator: initial state has " + std::to_string(y0.size()) +
                           " entries, the system " + std::to_string(size_));
  }
  try {
    // context and state vector
    if (SUNContext_Create(nullptr, &ctx_) != 0 || ctx_ == nullptr) {
      throw IntegrationError("SUNContext_Create failed");
    }
    y_ = N_VNew_Serial(size_, ctx_);
    if (y_ == nullptr) throw IntegrationError("N_VNew_Serial failed");
    // fused vector kernels cut the number of vector calls per step
    check(N_VEnableFusedOps_Serial(y_, SUNTRUE), "N_VEnableFusedOps_Serial");
    for (int i = 0; i < size_; ++i) NV_Ith_S(y_, i) = y0[i];

    // CVODE memory, tolerances, callbacks
    const int lmm = options.method == CvodeMethod::kBdf ? CV_BDF : CV_ADAMS;
    cvode_ = CVodeCreate(lmm, ctx_);
    if (cvode_ == nullptr) throw IntegrationError("CVodeCreate failed");
    check(CVodeSetErrHandlerFn(cvode_, &CvodeIntegrator::error_handler, this),
          "CVodeSetErrHandlerFn");
    check(CVodeInit(cvode_, &CvodeIntegrator::rhs_callback, t0, y_), "CVodeInit");
    check(CVodeSStolerances(cvode_, options.relative_tolerance, options.absolute_tolerance),
          "CVodeSStolerances");
    check(CVodeSetUserData(cvode_, this), "CVodeSetUserData");
    check(CVodeSetMaxNumSteps(cvode_, options.max_steps_per_call), "CVodeSetMaxNumSteps");

    // Newton with a banded Jacobian where the system's is (a muscle's states depend on its
    // own: its difference quotients take half_bandwidth * 2 + 1 right-hand sides, not one
    // per state, and its LU grows with the muscles, not their cube), else dense
    const int band = system.half_bandwidth();
    if (band < size_ - 1) {
      matrix_ = SUNBandMatrix(size_, band, band, ctx_);
      if (matrix_ == nullptr) throw IntegrationError("SUNBandMatrix failed");
      solver_ = SUNLinSol_Band(y_, matrix_, ctx_);
      if (solver_ == nullptr) throw IntegrationError("SUNLinSol_Band failed");
    } else {
      matrix_ = SUNDenseMatrix(size_, size_, ctx_);
      if (matrix_ == nullptr) throw IntegrationError("SUNDenseMatrix failed");
      solver_ = SUNLinSol_Dense(y_, matrix_, ctx_);
      if (solver_ == nullptr) throw IntegrationError("SUNLinSol_Dense failed");
    }
    check(CVodeSetLinearSolver(cvode_, solver_, matrix_), "CVodeSetLinearSolver");
  } catch (...) {
    free_all();
    throw;
  }
}

CvodeIntegrator::~CvodeIntegrator() { free_all(); }

void CvodeIntegrator::free_all() {
  // reverse order of creation; each Destroy/Free accepts only what was created
  if (cvode_ != nullptr) CVodeFree(&cvode_);
  if (solver_ != nullptr) SUNLinSolFree(solver_);
  if (matrix_ != nullptr) SUNMatDestroy(matrix_);
  if (y_ != nullptr) N_VDestroy(y_);
  if (ctx_ != nullptr) SUNContext_Free(&ctx_);
  cvode_ = nullptr;
  solver_ = nullptr;
  matrix_ = nullptr;
  y_ = nullptr;
  ctx_ = nullptr;
}

void CvodeIntegrator::check(int flag, const char* function) const {
  if (flag >= 0) return;
  std::string message = std::string(function) + " failed: " + flag_name(flag);
  if (!last_message_.empty()) message += " (" + last_message_ + ")";
  throw IntegrationError(message);
}

void CvodeIntegrator::error_handler(int code, const char* module, const char* function, char* msg,
                                    void* user_data) {
  // keep CVODE's own explanation for the exception message instead of printing it
  auto* self = static_cast<CvodeIntegrator*>(user_data);
  if (code < 0) {
    self->last_message_ = std::string(module) + "/" + function + ": " + msg;
  }
}

int CvodeIntegrator::rhs_callback(double t, N_Vector y, N_Vector ydot, void* user_data) {
  // no exception may cross into C: store it and tell CVODE to stop (-1) or retry (+1)
  auto* self = static_cast<CvodeIntegrator*>(user_data);
  try {
    self->system_.rhs(t, NV_DATA_S(y), NV_DATA_S(ydot));
    return 0;
  } catch (const RecoverableRhsError&) {
    return 1;
  } catch (...) {
    self->rhs_exception_ = std::current_exception();
    return -1;
  }
}

void CvodeIntegrator::reset(double t0, const std::vector<double>& y0) {
  if (static_cast<int>(y0.size()) != size_) {
    throw IntegrationError("CvodeIntegrator::reset: state has " + std::to_string(y0.size()) +
                           " entries, the system " + std::to_string(size_));
  }
  // CVodeReInit zeroes CVODE's counters: keep the totals
  steps_before_reset_ = steps();
  rhs_evals_before_reset_ = rhs_evals();
  error_test_failures_before_reset_ = error_test_failures();
  jacobian_evals_before_reset_ = jacobian_evals();
  for (int i = 0; i < size_; ++i) NV_Ith_S(y_, i) = y0[i];
  rhs_exception_ = nullptr;
  last_message_.clear();
  check(CVodeReInit(cvode_, t0, y_), "CVodeReInit");
  t_ = t0;
}

void CvodeIntegrator::advance_to(double t_end) {
  if (!(t_end >= t_)) {
    throw IntegrationError("CvodeIntegrator::advance_to: t_end " + std::to_string(t_end) +
                           " s is before the current time " + std::to_string(t_) + " s");
  }
  if (t_end == t_) return;
  // stop exactly at t_end: inputs change there
  check(CVodeSetStopTime(cvode_, t_end), "CVodeSetStopTime");
  sunrealtype t_reached = t_;
  const int flag = CVode(cvode_, t_end, y_, &t_reached, CV_NORMAL);
  if (flag < 0) {
    std::string message =
        "CVode failed at t = " + std::to_string(t_reached) + " s: " + flag_name(flag);
    if (rhs_exception_) {
      std::exception_ptr e = rhs_exception_;
      rhs_exception_ = nullptr;
      try {
        std::rethrow_exception(e);
      } catch (const std::exception& inner) {
        message += ": right-hand side threw: " + std::string(inner.what());
      } catch (...) {
        message += ": right-hand side threw a non-standard exception";
      }
    } else if (!last_message_.empty()) {
      message += " (" + last_message_ + ")";
    }
    throw IntegrationError(message);
  }
  // CVODE returns exactly the stop time
  t_ = t_end;
}

const double* CvodeIntegrator::state() const { return NV_DATA_S(y_); }

long CvodeIntegrator::counter(int (*get)(void*, long*), const char* function) const {
  long n = 0;
  check(get(cvode_, &n), function);
  return n;
}

long CvodeIntegrator::steps() const {
  return steps_before_reset_ + counter(CVodeGetNumSteps, "CVodeGetNumSteps");
}

long CvodeIntegrator::rhs_evals() const {
  return rhs_evals_before_reset_ + counter(CVodeGetNumRhsEvals, "CVodeGetNumRhsEvals") +
         counter(CVodeGetNumLinRhsEvals, "CVodeGetNumLinRhsEvals");
}

long CvodeIntegrator::error_test_failures() const {
  return error_test_failures_before_reset_ +
         counter(CVodeGetNumErrTestFails, "CVodeGetNumErrTestFails");
}

long CvodeIntegrator::jacobian_evals() const {
  return jacobian_evals_before_reset_ + counter(CVodeGetNumJacEvals, "CVodeGetNumJacEvals");
}

}  // namespace pamsim
