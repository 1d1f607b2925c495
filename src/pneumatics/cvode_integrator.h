// cvode_integrator.h: integrates an OdeSystem (ode_system.h) with SUNDIALS CVODE 6.4.
// It owns every SUNDIALS object (SUNContext, N_Vector, SUNMatrix, SUNLinearSolver, CVODE
// memory), checks every return flag and frees everything in its destructor. One instance
// per trial / thread (a SUNContext must not be shared between threads).
//
// Stepping: advance_to(t) sets CVODE's stop time to t, so CVODE never integrates past the
// end of the caller's step with inputs that belong to the next step; the history (order,
// step size, Nordsieck array) is kept between calls (a warm restart). reset() re-initialises
// CVODE (order 1, new initial step) for a discontinuity in the state.
#pragma once

#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "pneumatics/ode_system.h"

// SUNDIALS handle types, forward-declared so that users of this header do not need the
// SUNDIALS include path (pneumatics links SUNDIALS privately).
struct _SUNContext;
struct _generic_N_Vector;
struct _generic_SUNMatrix;
struct _generic_SUNLinearSolver;

namespace pamsim {

// A SUNDIALS call failed; the message names the function and the flag
// (CVodeGetReturnFlagName), and for a failed right-hand side what it threw.
// After it the integrator must be reset() before advancing again.
class IntegrationError : public std::runtime_error {
 public:
  explicit IntegrationError(const std::string& message) : std::runtime_error(message) {}
};

// The SUNDIALS library's version ("6.4.1"), as it reports itself (SUNDIALSGetVersion), for
// the provenance of outputs.
std::string sundials_version();

struct CvodeOptions {
  // BDF or Adams, with Newton on a dense or banded Jacobian (OdeSystem::half_bandwidth)
  CvodeMethod method = CvodeMethod::kBdf;
  double relative_tolerance = 1e-6;
  double absolute_tolerance = 0.1;  // in the state's units (Pa here)
  long max_steps_per_call = 5000;   // CVodeSetMaxNumSteps
};

class CvodeIntegrator {
 public:
  // `system` must outlive the integrator. y0 has system.size() entries.
  // Throws IntegrationError if a SUNDIALS allocation or setting fails.
  CvodeIntegrator(OdeSystem& system, const CvodeOptions& options, double t0,
                  const std::vector<double>& y0);
  ~CvodeIntegrator();
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

  // re-initialise at (t0, y0): CVODE restarts at order 1 (CVodeReInit)
  void reset(double t0, const std::vector<double>& y0);
  // integrate to t_end >= time() with stop time t_end; throws IntegrationError (an
  // exception thrown by the right-hand side is reported in its message)
  void advance_to(double t_end);

  double time() const { return t_; }
  const double* state() const;
  int size() const { return size_; }

  // cumulative since construction (across reset()): internal steps, right-hand-side evaluations
  // (including the ones for difference-quotient Jacobians), error-test failures, Jacobian
  // evaluations
  long steps() const;
  long rhs_evals() const;
  long error_test_failures() const;
  long jacobian_evals() const;

 private:
  static int rhs_callback(double t, _generic_N_Vector* y, _generic_N_Vector* ydot, void* user_data);
  static void error_handler(int code, const char* module, const char* function, char* msg,
                            void* user_data);
  void check(int flag, const char* function) const;
  // A CVODE counter since the last (re)initialisation, read by `get`, named `function`.
  long counter(int (*get)(void*, long*), const char* function) const;
  void free_all();

  OdeSystem& system_;
  int size_ = 0;
  double t_ = 0.0;
  _SUNContext* ctx_ = nullptr;
  _generic_N_Vector* y_ = nullptr;
  _generic_SUNMatrix* matrix_ = nullptr;
  _generic_SUNLinearSolver* solver_ = nullptr;
  void* cvode_ = nullptr;  // CVODE memory
  long steps_before_reset_ = 0;
  long rhs_evals_before_reset_ = 0;
  long error_test_failures_before_reset_ = 0;
  long jacobian_evals_before_reset_ = 0;
  std::exception_ptr rhs_exception_;
  std::string last_message_;
};

}  // namespace pamsim
