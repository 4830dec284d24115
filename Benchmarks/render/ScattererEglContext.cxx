#include "ScattererEglContext.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkGenericOpenGLRenderWindow.h"
#include "vtkNew.h"
#include "vtk_glew.h"

#include <EGL/eglext.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <string>
#include <vector>

namespace
{
EGLDisplay g_display = EGL_NO_DISPLAY;
EGLContext g_context = EGL_NO_CONTEXT;

const char* Str(const char* s)
{
  return s ? s : "(null)";
}

const char* EglErr()
{
  static char buf[32];
  std::snprintf(buf, sizeof buf, "0x%04x", eglGetError());
  return buf;
}

bool Env(const char* name)
{
  const char* v = std::getenv(name);
  return v && *v && std::strcmp(v, "0") != 0;
}

// Errors VTK reports while taking over the context (e.g. "GLEW could not be initialized").
int g_vtkErrors = 0;
void OnVtkError(vtkObject*, unsigned long, void*, void* callData)
{
  ++g_vtkErrors;
  std::printf("VTK error: %s\n", callData ? static_cast<const char*>(callData) : "?");
}

EGLDisplay InitDisplay(EGLDisplay dpy, const char* what)
{
  EGLint major = 0, minor = 0;
  if (dpy == EGL_NO_DISPLAY)
  {
    std::printf("EGL: %s: no display (%s)\n", what, EglErr());
    return EGL_NO_DISPLAY;
  }
  if (!eglInitialize(dpy, &major, &minor))
  {
    std::printf("EGL: %s: eglInitialize failed (%s)\n", what, EglErr());
    return EGL_NO_DISPLAY;
  }
  std::printf("EGL: using %s: EGL %d.%d, vendor \"%s\", version \"%s\", client APIs \"%s\"\n", what,
    major, minor, Str(eglQueryString(dpy, EGL_VENDOR)), Str(eglQueryString(dpy, EGL_VERSION)),
    Str(eglQueryString(dpy, EGL_CLIENT_APIS)));
  return dpy;
}

EGLDisplay OpenDisplay()
{
  const char* clientExt = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  std::printf("EGL client extensions: %s\n", Str(clientExt));
  auto queryDevices =
    reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  auto queryDeviceString =
    reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
    eglGetProcAddress("eglGetPlatformDisplayEXT"));
  const bool hasDevice = clientExt && std::strstr(clientExt, "EGL_EXT_platform_device");
  if (!Env("SCATTERER_EGL_DEFAULT") && hasDevice && queryDevices && getPlatformDisplay)
  {
    EGLint n = 0;
    std::vector<EGLDeviceEXT> devices(16);
    if (queryDevices(16, devices.data(), &n) && n > 0)
    {
      const char* pick = std::getenv("SCATTERER_EGL_DEVICE");
      for (EGLint i = 0; i < n; ++i)
      {
        if (pick && *pick && std::atoi(pick) != i)
          continue;
        const char* dext =
          queryDeviceString ? queryDeviceString(devices[i], EGL_EXTENSIONS) : nullptr;
        const char* drm = (dext && std::strstr(dext, "EGL_EXT_device_drm") && queryDeviceString)
          ? queryDeviceString(devices[i], EGL_DRM_DEVICE_FILE_EXT)
          : nullptr;
        std::printf(
          "EGL device %d of %d: extensions \"%s\" drm \"%s\"\n", i, n, Str(dext), Str(drm));
        const std::string what = "EGL_PLATFORM_DEVICE_EXT device " + std::to_string(i);
        EGLDisplay dpy = InitDisplay(
          getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr), what.c_str());
        if (dpy != EGL_NO_DISPLAY)
          return dpy;
      }
    }
    else
    {
      std::printf("EGL: eglQueryDevicesEXT found no device (%s)\n", EglErr());
    }
  }
  return InitDisplay(eglGetDisplay(EGL_DEFAULT_DISPLAY), "EGL_DEFAULT_DISPLAY");
}

void OnMakeCurrent(vtkObject*, unsigned long, void* client, void*)
{
  static_cast<scatterer_egl::Context*>(client)->MakeCurrent();
}
void OnIsCurrent(vtkObject*, unsigned long, void* client, void* callData)
{
  auto* c = static_cast<scatterer_egl::Context*>(client);
  *static_cast<bool*>(callData) = c->Ctx != EGL_NO_CONTEXT && eglGetCurrentContext() == c->Ctx;
}
void OnFrame(vtkObject*, unsigned long, void* client, void*)
{
  auto* c = static_cast<scatterer_egl::Context*>(client);
  if (c->Surface != EGL_NO_SURFACE)
    eglSwapBuffers(c->Display, c->Surface); // no-op for a pbuffer
}
void OnYes(vtkObject*, unsigned long, void*, void* callData)
{
  *static_cast<int*>(callData) = 1;
}
}

// ---------------------------------------------------------------------------------------------
// GLX shim for GLEW. Debian's GLEW is the GLX build: glewInit() = glewContextInit() (GL entry
// points; works with any current context through glvnd's dispatch) + glxewInit(), which returns
// GLEW_ERROR_NO_GLX_DISPLAY when glXGetCurrentDisplay() is NULL, as it is with an EGL context.
// VTK 9.1 then refuses the context. libGLEW gets glXGetCurrentDisplay through
// glXGetProcAddressARB and calls glXQueryVersion / glXGetClientString directly: while our EGL
// context is current and GLX has no display, these answer with a dummy display, GLX 1.4 and no
// GLX extensions. Otherwise (and with SCATTERER_EGL_NO_GLX_SHIM=1) they forward to libGLX.
// The executable is linked with -rdynamic so these definitions take precedence.
namespace
{
struct DummyDisplay
{
  char pad[4096];
} g_dummyDisplay;

bool ShimActive()
{
  static const bool off = Env("SCATTERER_EGL_NO_GLX_SHIM");
  return !off && g_context != EGL_NO_CONTEXT && eglGetCurrentContext() == g_context;
}
template <typename F>
F Real(const char* name)
{
  return reinterpret_cast<F>(dlsym(RTLD_NEXT, name));
}
using GetProcFn = void (*(*)(const unsigned char*))();
using GetDisplayFn = void* (*)();
void* ShimGetCurrentDisplay()
{
  static auto real = Real<GetProcFn>("glXGetProcAddressARB");
  static auto realGet = real ? reinterpret_cast<GetDisplayFn>(real(
                                 reinterpret_cast<const unsigned char*>("glXGetCurrentDisplay")))
                             : nullptr;
  void* d = realGet ? realGet() : nullptr;
  if (!d && ShimActive())
  {
    static bool said = false;
    if (!said)
      std::printf("EGL: GLX shim: GLEW asked for the current GLX display; answering a dummy one\n");
    said = true;
    return &g_dummyDisplay;
  }
  return d;
}
}

extern "C"
{
  __attribute__((visibility("default"))) void (*glXGetProcAddressARB(const unsigned char* name))()
  {
    static auto real = Real<GetProcFn>("glXGetProcAddressARB");
    if (name && std::strcmp(reinterpret_cast<const char*>(name), "glXGetCurrentDisplay") == 0 &&
      !Env("SCATTERER_EGL_NO_GLX_SHIM"))
      return reinterpret_cast<void (*)()>(&ShimGetCurrentDisplay);
    return real ? real(name) : nullptr;
  }
  __attribute__((visibility("default"))) int glXQueryVersion(void* dpy, int* major, int* minor)
  {
    if (dpy == &g_dummyDisplay)
    {
      if (major)
        *major = 1;
      if (minor)
        *minor = 4;
      return 1;
    }
    static auto real = Real<int (*)(void*, int*, int*)>("glXQueryVersion");
    return real ? real(dpy, major, minor) : 0;
  }
  __attribute__((visibility("default"))) const char* glXGetClientString(void* dpy, int name)
  {
    if (dpy == &g_dummyDisplay)
      return "";
    static auto real = Real<const char* (*)(void*, int)>("glXGetClientString");
    return real ? real(dpy, name) : nullptr;
  }
}

namespace scatterer_egl
{
Context::~Context()
{
  if (this->Display != EGL_NO_DISPLAY)
  {
    eglMakeCurrent(this->Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (this->Surface != EGL_NO_SURFACE)
      eglDestroySurface(this->Display, this->Surface);
    if (this->Ctx != EGL_NO_CONTEXT)
      eglDestroyContext(this->Display, this->Ctx);
    eglTerminate(this->Display);
  }
  g_context = EGL_NO_CONTEXT;
  g_display = EGL_NO_DISPLAY;
}

bool Context::MakeCurrent()
{
  if (eglGetCurrentContext() == this->Ctx && eglGetCurrentSurface(EGL_DRAW) == this->Surface)
    return true;
  if (!eglMakeCurrent(this->Display, this->Surface, this->Surface, this->Ctx))
  {
    std::fprintf(stderr, "EGL: eglMakeCurrent failed (%s)\n", EglErr());
    return false;
  }
  return true;
}

bool Context::Create(int width, int height)
{
  this->Display = OpenDisplay();
  if (this->Display == EGL_NO_DISPLAY)
    return false;
  if (!eglBindAPI(EGL_OPENGL_API))
  {
    std::printf("EGL: eglBindAPI(EGL_OPENGL_API) failed (%s)\n", EglErr());
    return false;
  }
  const char* ext = eglQueryString(this->Display, EGL_EXTENSIONS);
  const bool surfaceless = ext && std::strstr(ext, "EGL_KHR_surfaceless_context");
  EGLConfig config = nullptr;
  EGLint count = 0;
  bool pbuffer = !Env("SCATTERER_EGL_SURFACELESS");
  const EGLint pbufferAttribs[] = { EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RED_SIZE, 8,
    EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_RENDERABLE_TYPE,
    EGL_OPENGL_BIT, EGL_NONE };
  if (!pbuffer || !eglChooseConfig(this->Display, pbufferAttribs, &config, 1, &count) || count < 1)
  {
    if (pbuffer)
      std::printf("EGL: no pbuffer RGBA8/D24 OpenGL config (%s)\n", EglErr());
    pbuffer = false;
    const EGLint anyAttribs[] = { EGL_SURFACE_TYPE, 0, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
      EGL_NONE };
    if (!surfaceless || !eglChooseConfig(this->Display, anyAttribs, &config, 1, &count) ||
      count < 1)
    {
      std::printf("EGL: no usable OpenGL config (surfaceless %d, %s)\n", surfaceless, EglErr());
      return false;
    }
  }
  struct Try
  {
    const char* Name;
    std::vector<EGLint> Attribs;
  };
  std::vector<Try> tries;
  if (!Env("SCATTERER_EGL_COMPAT"))
    tries.push_back({ "3.2 core",
      { EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 2, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE } });
  tries.push_back({ "3.2 compatibility",
    { EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 2, EGL_CONTEXT_OPENGL_PROFILE_MASK,
      EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE } });
  tries.push_back({ "default", { EGL_NONE } });
  for (const Try& t : tries)
  {
    this->Ctx = eglCreateContext(this->Display, config, EGL_NO_CONTEXT, t.Attribs.data());
    if (this->Ctx != EGL_NO_CONTEXT)
    {
      std::printf("EGL: OpenGL context requested as %s\n", t.Name);
      break;
    }
    std::printf("EGL: no %s context (%s)\n", t.Name, EglErr());
  }
  if (this->Ctx == EGL_NO_CONTEXT)
    return false;
  if (pbuffer)
  {
    const EGLint surfAttribs[] = { EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE };
    this->Surface = eglCreatePbufferSurface(this->Display, config, surfAttribs);
    if (this->Surface == EGL_NO_SURFACE)
    {
      std::printf("EGL: eglCreatePbufferSurface %dx%d failed (%s)%s\n", width, height, EglErr(),
        surfaceless ? "; going surfaceless" : "");
      if (!surfaceless)
        return false;
    }
  }
  std::printf("EGL: %s\n",
    this->Surface != EGL_NO_SURFACE
      ? ("pbuffer " + std::to_string(width) + "x" + std::to_string(height)).c_str()
      : "surfaceless (VTK's own framebuffer only)");
  g_display = this->Display;
  g_context = this->Ctx;
  if (!this->MakeCurrent())
    return false;
  return true;
}

void Context::Attach(vtkGenericOpenGLRenderWindow* window)
{
  auto add = [&](unsigned long event, void (*fn)(vtkObject*, unsigned long, void*, void*))
  {
    vtkNew<vtkCallbackCommand> cb;
    cb->SetCallback(fn);
    cb->SetClientData(this);
    window->AddObserver(event, cb);
  };
  add(vtkCommand::WindowMakeCurrentEvent, OnMakeCurrent);
  add(vtkCommand::WindowIsCurrentEvent, OnIsCurrent);
  add(vtkCommand::WindowFrameEvent, OnFrame);
  add(vtkCommand::WindowSupportsOpenGLEvent, OnYes);
  add(vtkCommand::WindowIsDirectEvent, OnYes);
  if (this->Surface == EGL_NO_SURFACE)
    window->SetFrameBlitModeToNoBlit(); // there is no default framebuffer to blit into
}

bool Context::InitializeVtk(vtkGenericOpenGLRenderWindow* window)
{
  if (!this->MakeCurrent())
    return false;
  std::printf("GL_VENDOR: %s\nGL_RENDERER: %s\nGL_VERSION: %s\n",
    Str(reinterpret_cast<const char*>(glGetString(GL_VENDOR))),
    Str(reinterpret_cast<const char*>(glGetString(GL_RENDERER))),
    Str(reinterpret_cast<const char*>(glGetString(GL_VERSION))));
  std::fflush(stdout);
  glewExperimental = GL_TRUE;
  window->SetOwnContext(false);
  window->SetIsCurrent(true);
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(OnVtkError);
  const unsigned long tag = window->AddObserver(vtkCommand::ErrorEvent, onError);
  g_vtkErrors = 0;
  window->InitializeFromCurrentContext();
  window->RemoveObserver(tag);
  std::printf("VTK: InitializeFromCurrentContext: %s\n",
    g_vtkErrors ? "reported errors (with the GLX shim off, VTK re-runs glewInit every frame)"
                : "OK (glewInit succeeded)");
  std::fflush(stdout);
  return true;
}
}
