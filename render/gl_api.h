#pragma once
// The one header that includes OpenGL, for render/ only (nothing outside render/ sees GL).
// Mesa's libOSMesa exports every GL entry point up to 4.5, so we call the prototypes directly
// instead of going through a function loader. The same file is force-included into Dear ImGui's
// OpenGL3 backend, built with IMGUI_IMPL_OPENGL_LOADER_CUSTOM (see render/CMakeLists.txt).
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
