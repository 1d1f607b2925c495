/* pamctl_math.h: the library's arithmetic in its own type (pamctl_real, double or float):
 * the <math.h> functions of that type, its limits, and a literal of that type, so a float
 * build promotes nothing to double (-Wdouble-promotion). Internal to the library. */
#ifndef PAMCTL_MATH_H
#define PAMCTL_MATH_H

#include <math.h>

#include "pamctl.h"

#ifdef PAMCTL_FLOAT
#define PAMCTL_R(x) x##f
#define pamctl_sqrt sqrtf
#define pamctl_cbrt cbrtf
#define pamctl_fabs fabsf
#define pamctl_copysign copysignf
#define PAMCTL_REAL_MAX 0x1.fffffep+127f
#define PAMCTL_EPSILON 0x1p-23f
#else
#define PAMCTL_R(x) x
#define pamctl_sqrt sqrt
#define pamctl_cbrt cbrt
#define pamctl_fabs fabs
#define pamctl_copysign copysign
#define PAMCTL_REAL_MAX 0x1.fffffffffffffp+1023
#define PAMCTL_EPSILON 0x1p-52
#endif

/* isfinite is type-generic in C99 */
#define pamctl_isfinite(x) isfinite(x)

#endif /* PAMCTL_MATH_H */
