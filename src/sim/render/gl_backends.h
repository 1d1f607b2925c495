// gl_backends.h: what gl_context.cc needs of its backends, one file each: the OSMesa
// context (osmesa_context.cc) and the EGL one (egl_context.cc, built where the EGL headers
// are: PAMSIM_HAVE_EGL). Internal to src/sim/render; the interface is gl_context.h.
#pragma once

#include <memory>
#include <string>

#include "sim/render/gl_context.h"

namespace pamsim {

// glGetString as a backend resolves it (the linked one may belong to another library)
using GlGetString = const unsigned char* (*)(unsigned int);

// "<vendor>, <renderer>, OpenGL <version>" of the current context, through `get_string`;
// "unknown (no glGetString)" without one.
std::string gl_strings(GlGetString get_string);

// An OSMesa context of width x height, current on return. `fallback_reason`: why egl, asked
// for, was not used (empty: osmesa was asked for). Throws InputError if OSMesa fails.
std::unique_ptr<GlContext> make_osmesa_context(int width, int height,
                                               const std::string& fallback_reason = "");

#ifdef PAMSIM_HAVE_EGL
// An EGL context on the device `choice` names, else the first that gives one (gl_context.h),
// current on return. Throws InputError when libEGL is unusable or no display gives a context.
std::unique_ptr<GlContext> make_egl_context(const EglDeviceChoice& choice);
#endif

}  // namespace pamsim
