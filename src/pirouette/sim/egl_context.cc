#include "pirouette/sim/egl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>

#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "pirouette/sim/renderer.h"

namespace pirouette::sim {
namespace {

bool HasExtension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = std::strstr(list, name); p != nullptr; p = std::strstr(p + 1, name)) {
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  }
  return false;
}

template <typename F>
F Proc(const char* name) {
  return reinterpret_cast<F>(eglGetProcAddress(name));
}

// A display on a hardware GPU, through EGL_EXT_device_enumeration, if any.
EGLDisplay HardwareDisplay() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!HasExtension(client, "EGL_EXT_device_enumeration") ||
      !HasExtension(client, "EGL_EXT_platform_device")) {
    return EGL_NO_DISPLAY;
  }
  const auto query_devices = Proc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  const auto query_device_string = Proc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  const auto get_platform_display =
      Proc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  if (!query_devices || !query_device_string || !get_platform_display) return EGL_NO_DISPLAY;
  EGLint count = 0;
  if (!query_devices(0, nullptr, &count) || count <= 0) return EGL_NO_DISPLAY;
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  query_devices(count, devices.data(), &count);
  for (EGLDeviceEXT device : devices) {
    const char* extensions = query_device_string(device, EGL_EXTENSIONS);
    // Mesa's software device advertises EGL_MESA_device_software; a GPU has a DRM node.
    if (HasExtension(extensions, "EGL_MESA_device_software") ||
        !HasExtension(extensions, "EGL_EXT_device_drm")) {
      continue;
    }
    EGLDisplay display = get_platform_display(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
    if (display != EGL_NO_DISPLAY) return display;
  }
  return EGL_NO_DISPLAY;
}

EGLDisplay SurfacelessDisplay() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!HasExtension(client, "EGL_MESA_platform_surfaceless")) return EGL_NO_DISPLAY;
  const auto get_platform_display =
      Proc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  if (!get_platform_display) return EGL_NO_DISPLAY;
  return get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
}

EGLContext CreateContext(EGLDisplay display) {
  EGLint major = 0;
  EGLint minor = 0;
  if (!eglInitialize(display, &major, &minor)) return EGL_NO_CONTEXT;
  if (!eglBindAPI(EGL_OPENGL_API)) return EGL_NO_CONTEXT;
  const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  const bool no_config =
      HasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context");
  if (!eglChooseConfig(display, config_attributes, &config, 1, &configs) || configs < 1) {
    if (!no_config) return EGL_NO_CONTEXT;
    config = nullptr;  // EGL_NO_CONFIG_KHR
  }
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                       3,
                                       EGL_CONTEXT_MINOR_VERSION,
                                       3,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                       EGL_NONE};
  return eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
}

}  // namespace

EglContext EglContext::Create() {
  EglContext result;
  std::string tried;
  for (EGLDisplay display : {HardwareDisplay(), SurfacelessDisplay()}) {
    if (display == EGL_NO_DISPLAY) continue;
    EGLContext context = CreateContext(display);
    if (context == EGL_NO_CONTEXT) {
      tried += " (EGL error 0x" + [] {
        char buffer[16];
        std::snprintf(buffer, sizeof buffer, "%x", eglGetError());
        return std::string(buffer);
      }() + ")";
      eglTerminate(display);
      continue;
    }
    result.display_ = display;
    result.context_ = context;
    result.MakeCurrent();
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    result.renderer_name_ = name != nullptr ? name : "unknown";
    return result;
  }
  throw RenderError(
      "no headless OpenGL 3.3 through EGL: neither a GPU nor Mesa's surfaceless platform gave a "
      "context" +
      tried + "; install Mesa's EGL (Debian: libegl-mesa0 libgl1-mesa-dri)");
}

EglContext::~EglContext() { Release(); }

void EglContext::Release() {
  if (context_ != nullptr) {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    // The display is shared by every context in the process (EGL hands out
    // one per platform and device); it is left initialised for them.
    context_ = nullptr;
  }
}

EglContext::EglContext(EglContext&& other) noexcept
    : display_(std::exchange(other.display_, nullptr)),
      context_(std::exchange(other.context_, nullptr)),
      renderer_name_(std::move(other.renderer_name_)) {}

EglContext& EglContext::operator=(EglContext&& other) noexcept {
  if (this != &other) {
    Release();
    display_ = std::exchange(other.display_, nullptr);
    context_ = std::exchange(other.context_, nullptr);
    renderer_name_ = std::move(other.renderer_name_);
  }
  return *this;
}

void EglContext::MakeCurrent() const {
  if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
    throw RenderError("eglMakeCurrent failed");
  }
}

}  // namespace pirouette::sim
