/* pamctl_spring.c: Yoshida and Hosoda's spring laws, Eq. (2)-(5), and their inversion for
 * the deformation d, Eq. (10): the smallest positive root of a cubic in d, in closed form for
 * Eq. (3) and by bracketed Newton steps for Eq. (4) and (5). Every loop has a fixed bound. */
#include "pamctl_math.h"

/* exponents (i of p, j of d) of each term before the common factor d, paper order */
typedef struct {
  int8_t i;
  int8_t j;
} pamctl_term;
static const pamctl_term kEq3Terms[4] = {{0, 0}, {0, 1}, {1, 0}, {1, 1}};
static const pamctl_term kEq4Terms[6] = {{0, 0}, {0, 1}, {1, 0}, {0, 2}, {1, 1}, {2, 0}};
static const pamctl_term kEq5Terms[5] = {{0, 0}, {0, 2}, {1, 2}, {2, 1}, {3, 0}};

/* the law's terms, Eq. (3), (4) or (5), and their count */
static const pamctl_term* law_terms(int32_t law, int32_t* count) {
  switch (law) {
    case PAMCTL_LAW_EQ3:
      *count = 4;
      return kEq3Terms;
    case PAMCTL_LAW_EQ4:
      *count = 6;
      return kEq4Terms;
    case PAMCTL_LAW_EQ5:
      *count = 5;
      return kEq5Terms;
    default:
      *count = 0;
      return kEq3Terms;
  }
}

int32_t pamctl_law_term_count(int32_t law) {
  int32_t count = 0;
  (void)law_terms(law, &count);
  return count;
}

void pamctl_law_term(int32_t law, int32_t k, int32_t* p_exponent, int32_t* d_exponent) {
  int32_t count = 0;
  const pamctl_term* terms = law_terms(law, &count);
  *p_exponent = k >= 0 && k < count ? terms[k].i : 0;
  *d_exponent = k >= 0 && k < count ? terms[k].j : 0;
}

void pamctl_spring_polynomial(const pamctl_spring* spring, pamctl_real p_pa, pamctl_real a[3]) {
  int32_t count = 0;
  const pamctl_term* terms = law_terms(spring->law, &count);
  /* collect c_k p^i into the coefficient of d^(j+1) */
  const pamctl_real p_pow[4] = {PAMCTL_R(1.0), p_pa, p_pa * p_pa, p_pa * p_pa * p_pa};
  a[0] = a[1] = a[2] = PAMCTL_R(0.0);
  for (int k = 0; k < count; ++k) a[terms[k].j] += spring->coef[k] * p_pow[terms[k].i];
}

/* smallest positive root of a2 x^2 + a1 x - f = 0, f > 0, by the stable form
 * q = -(a1 + sgn(a1) sqrt(disc)) / 2, roots q/a2 and -f/q; -1 if none */
static pamctl_real quadratic_root(pamctl_real a2, pamctl_real a1, pamctl_real f) {
  /* linear limit */
  if (a2 == PAMCTL_R(0.0)) return a1 > PAMCTL_R(0.0) ? f / a1 : PAMCTL_R(-1.0);
  const pamctl_real disc = a1 * a1 + PAMCTL_R(4.0) * a2 * f;
  if (!(disc >= PAMCTL_R(0.0))) return PAMCTL_R(-1.0);
  /* both roots without cancellation; keep the smallest positive finite one */
  const pamctl_real q = PAMCTL_R(-0.5) * (a1 + pamctl_copysign(pamctl_sqrt(disc), a1));
  if (q == PAMCTL_R(0.0)) return PAMCTL_R(-1.0);
  const pamctl_real roots[2] = {q / a2, -f / q};
  pamctl_real best = PAMCTL_R(-1.0);
  for (int k = 0; k < 2; ++k) {
    const pamctl_real r = roots[k];
    if (r > PAMCTL_R(0.0) && pamctl_isfinite(r) && (best < PAMCTL_R(0.0) || r < best)) best = r;
  }
  return best;
}

/* g(x) = a3 x^3 + a2 x^2 + a1 x - f, in Horner form */
typedef struct {
  pamctl_real a3, a2, a1, f;
} pamctl_cubic;
static pamctl_real cubic_value(const pamctl_cubic* g, pamctl_real x) {
  return ((g->a3 * x + g->a2) * x + g->a1) * x - g->f;
}
static pamctl_real cubic_slope(const pamctl_cubic* g, pamctl_real x) {
  return (PAMCTL_R(3.0) * g->a3 * x + PAMCTL_R(2.0) * g->a2) * x + g->a1;
}

/* root of g in [lo, hi] where g(lo) < 0 <= g(hi), g monotone: Newton steps kept inside the
 * bracket, bisection when a step leaves it; converges to a few ulps */
static pamctl_real bracketed_newton(const pamctl_cubic* g, pamctl_real lo, pamctl_real hi,
                                    pamctl_real x) {
  for (int it = 0; it < 100; ++it) {
    const pamctl_real gx = cubic_value(g, x);
    if (gx == PAMCTL_R(0.0)) return x;
    if (gx < PAMCTL_R(0.0))
      lo = x;
    else
      hi = x;
    pamctl_real next = x - gx / cubic_slope(g, x);
    if (!(next > lo && next < hi)) next = PAMCTL_R(0.5) * (lo + hi);
    if (pamctl_fabs(next - x) <= PAMCTL_R(4.0) * PAMCTL_EPSILON * pamctl_fabs(next)) return next;
    x = next;
  }
  return x;
}

/* the smaller of two reals as std::min orders them: b < a ? b : a */
static pamctl_real min_of(pamctl_real a, pamctl_real b) { return b < a ? b : a; }

/* first upper end where g >= 0 beyond `from`, by doubling a scale guess; -1 if none found */
static pamctl_real bracket_above(const pamctl_cubic* g, pamctl_real from) {
  pamctl_real step = from < PAMCTL_R(0.0) ? PAMCTL_R(0.0) : from;
  if (step == PAMCTL_R(0.0)) {
    /* scale guess from the dominant terms alone: f/|a1|, sqrt(f/|a2|), cbrt(f/|a3|) */
    step = PAMCTL_REAL_MAX;
    if (g->a1 != PAMCTL_R(0.0)) step = min_of(step, g->f / pamctl_fabs(g->a1));
    if (g->a2 != PAMCTL_R(0.0)) step = min_of(step, pamctl_sqrt(g->f / pamctl_fabs(g->a2)));
    if (g->a3 != PAMCTL_R(0.0)) step = min_of(step, pamctl_cbrt(g->f / pamctl_fabs(g->a3)));
  }
  pamctl_real hi = from + step;
  for (int it = 0; it < 2100 && pamctl_isfinite(hi); ++it) {
    if (cubic_value(g, hi) >= PAMCTL_R(0.0)) return hi;
    hi = from + PAMCTL_R(2.0) * (hi - from);
  }
  return PAMCTL_R(-1.0);
}

/* Newton's start inside (lo, hi): the root without the cubic term when it falls there, else
 * the middle */
static pamctl_real initial_guess(const pamctl_cubic* g, pamctl_real lo, pamctl_real hi) {
  const pamctl_real x = quadratic_root(g->a2, g->a1, g->f);
  return x > lo && x < hi ? x : PAMCTL_R(0.5) * (lo + hi);
}

/* the positive critical points of g (roots of 3 a3 x^2 + 2 a2 x + a1), ascending */
static int critical_points(const pamctl_cubic* g, pamctl_real crit[2]) {
  const pamctl_real qa = PAMCTL_R(3.0) * g->a3, qb = PAMCTL_R(2.0) * g->a2;
  const pamctl_real disc = qb * qb - PAMCTL_R(4.0) * qa * g->a1;
  int n = 0;
  if (disc > PAMCTL_R(0.0)) {
    const pamctl_real q = PAMCTL_R(-0.5) * (qb + pamctl_copysign(pamctl_sqrt(disc), qb));
    const pamctl_real roots[2] = {q / qa, q != PAMCTL_R(0.0) ? g->a1 / q : PAMCTL_R(-1.0)};
    for (int k = 0; k < 2; ++k) {
      if (roots[k] > PAMCTL_R(0.0) && pamctl_isfinite(roots[k])) crit[n++] = roots[k];
    }
    if (n == 2 && crit[0] > crit[1]) {
      const pamctl_real t = crit[0];
      crit[0] = crit[1];
      crit[1] = t;
    }
  }
  return n;
}

/* cubic case: g(0) = -f < 0 and g is monotone between its positive critical points, so the
 * first piece whose right end has g >= 0 holds the smallest positive root; the last piece is
 * unbounded and is bracketed by doubling */
static pamctl_real cubic_root(pamctl_real a3, pamctl_real a2, pamctl_real a1, pamctl_real f) {
  const pamctl_cubic g = {a3, a2, a1, f};
  pamctl_real crit[2];
  const int n_crit = critical_points(&g, crit);

  /* walk the monotone pieces */
  pamctl_real lo = PAMCTL_R(0.0);
  for (int k = 0; k < n_crit; ++k) {
    const pamctl_real gk = cubic_value(&g, crit[k]);
    if (gk == PAMCTL_R(0.0)) return crit[k];
    if (gk > PAMCTL_R(0.0))
      return bracketed_newton(&g, lo, crit[k], initial_guess(&g, lo, crit[k]));
    lo = crit[k];
  }

  /* last piece: a root only if g grows without bound */
  if (!(a3 > PAMCTL_R(0.0))) return PAMCTL_R(-1.0);
  const pamctl_real hi = bracket_above(&g, lo);
  if (hi < PAMCTL_R(0.0)) return PAMCTL_R(-1.0);
  return bracketed_newton(&g, lo, hi, initial_guess(&g, lo, hi));
}

pamctl_real pamctl_smallest_positive_root(pamctl_real a3, pamctl_real a2, pamctl_real a1,
                                          pamctl_real f) {
  if (!(f > PAMCTL_R(0.0)) || !pamctl_isfinite(f) || !pamctl_isfinite(a1) || !pamctl_isfinite(a2) ||
      !pamctl_isfinite(a3)) {
    return PAMCTL_R(-1.0);
  }
  if (a3 == PAMCTL_R(0.0)) return quadratic_root(a2, a1, f);
  return cubic_root(a3, a2, a1, f);
}

pamctl_inversion pamctl_invert_spring(const pamctl_spring* spring, pamctl_real p_pa,
                                      pamctl_real f_n, pamctl_real* d_m) {
  *d_m = PAMCTL_R(0.0);
  /* non-finite input: nothing physical to report */
  if (!pamctl_isfinite(p_pa) || !pamctl_isfinite(f_n)) return PAMCTL_INVERSION_NO_ROOT;
  /* a slack line reads no force (Fig. 7): d = 0 */
  if (f_n <= PAMCTL_R(0.0)) return PAMCTL_INVERSION_SLACK;
  /* Eq. (3) is quadratic in d (A3 = 0): closed form; Eq. (4), (5) are cubic */
  pamctl_real a[3];
  pamctl_spring_polynomial(spring, p_pa, a);
  const pamctl_real d = pamctl_smallest_positive_root(a[2], a[1], a[0], f_n);
  if (!(d > PAMCTL_R(0.0) && pamctl_isfinite(d))) return PAMCTL_INVERSION_NO_ROOT;
  *d_m = d;
  return PAMCTL_INVERSION_OK;
}
