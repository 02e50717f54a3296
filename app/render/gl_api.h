#pragma once
// How this library reaches OpenGL (private header; never include it from a public one).
//
// Why prototypes instead of OSMesaGetProcAddress: libOSMesa itself exports every core entry point
// up to GL 4.3 (checked with `nm -D libOSMesa.so.8`), so linking against it needs no loader and
// no function-pointer tables; the same entry points serve EGL contexts (gl_context.h), and a build
// without OSMesa links GLVND's libOpenGL instead. The GL 4.5 direct-state-access functions (glNamedBufferData, ...)
// are NOT exported, so this code sticks to bind-to-edit calls. Never link libGL into the same
// process: its symbols would clash with OSMesa's (docs/architecture.md, "Rendering facts").
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
