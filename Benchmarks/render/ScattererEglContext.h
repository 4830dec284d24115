// A headless OpenGL context from EGL (no X server) for vtkGenericOpenGLRenderWindow,
// so the render benchmark runs on GPU machines without a display
// (scatterer-bench-render-egl; CMake option SCATTERER_BUILD_EGL_BENCHMARK). Debian's
// VTK 9.1 is a GLX build: see ScattererEglContext.cxx for how GLEW is satisfied.
#ifndef scatterer_egl_context_h
#define scatterer_egl_context_h

#include <EGL/egl.h>

class vtkGenericOpenGLRenderWindow;

namespace scatterer_egl
{
class Context
{
public:
  ~Context();
  /** Display (device platform, else default), desktop GL >= 3.2 (core, else compatibility),
   * a pbuffer of width x height (else surfaceless); made current. Prints what it got. */
  bool Create(int width, int height);
  /** Observers for make-current / is-current / frame / supports-OpenGL / is-direct. */
  void Attach(vtkGenericOpenGLRenderWindow* window);
  /** Makes current, InitializeFromCurrentContext, prints GL_VENDOR/RENDERER/VERSION. */
  bool InitializeVtk(vtkGenericOpenGLRenderWindow* window);

  EGLDisplay Display = EGL_NO_DISPLAY;
  EGLContext Ctx = EGL_NO_CONTEXT;
  EGLSurface Surface = EGL_NO_SURFACE;
  bool MakeCurrent();
};
}

#endif
