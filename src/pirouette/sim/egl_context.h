#pragma once

#include <string>

namespace pirouette::sim {

// A headless OpenGL 3.3 core context through EGL, with no window and no
// display server: a GPU's render node where there is one (EGL device
// platform), otherwise Mesa's surfaceless platform (llvmpipe on the CPU, as
// in CI). Throws RenderError when neither gives a context. Move-only.
class EglContext {
 public:
  static EglContext Create();
  ~EglContext();
  EglContext(EglContext&& other) noexcept;
  EglContext& operator=(EglContext&& other) noexcept;
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  // Makes this context current on the calling thread.
  void MakeCurrent() const;
  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  const std::string& renderer_name() const { return renderer_name_; }

 private:
  EglContext() = default;
  void Release();

  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
  std::string renderer_name_;
};

}  // namespace pirouette::sim
