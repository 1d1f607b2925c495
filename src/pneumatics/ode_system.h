// ode_system.h: an ODE as the integrator sees it (cvode_integrator.h), and nothing of what
// it models: f(t, y) -> ydot of a fixed size, its Jacobian's band, the error a right-hand
// side throws to ask for a smaller step, and the integration method. The pneumatics
// (chamber_ode.h) is one such system.
#pragma once

#include <stdexcept>
#include <string>

namespace pamsim {

// CVODE's linear multistep method: BDF (stiff) or Adams-Moulton
enum class CvodeMethod { kBdf, kAdams };

// f(t, y) -> ydot for an ODE of fixed size. rhs() may throw: RecoverableRhsError asks the
// integrator to retry with a smaller step (a non-physical trial state), anything else
// aborts the integration.
class OdeSystem {
 public:
  virtual ~OdeSystem() = default;
  virtual int size() const = 0;
  virtual void rhs(double t, const double* y, double* ydot) = 0;
  // How far from the diagonal dydot/dy can be non-zero (a system of independent blocks of
  // k states: k - 1); size() - 1, a dense Jacobian, unless a system says less.
  virtual int half_bandwidth() const { return size() - 1; }
};

// Thrown by rhs() for a trial state outside the model's domain (e.g. p <= 0 absolute).
class RecoverableRhsError : public std::runtime_error {
 public:
  explicit RecoverableRhsError(const std::string& m) : std::runtime_error(m) {}
};

}  // namespace pamsim
