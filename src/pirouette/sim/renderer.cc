#include "pirouette/sim/renderer.h"

#define GL_GLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "pirouette/sim/egl_context.h"
#include "pirouette/sim/scene_mesh.h"

// How a frame is made, in two OpenGL passes:
//  1. The scene through an ideal pinhole camera whose frustum covers every ray
//     the real (distorted) camera sees, into a multisampled float target,
//     resolved into a texture. Flat-shaded: ambient + Lambert from one
//     directional light; the floor is modulated by a seeded noise texture.
//  2. For every output pixel, a lookup texture built once from the camera
//     model gives where its undistorted ray falls in pass 1's image (so the
//     image is distorted exactly as CameraModel::Project distorts points);
//     then the vignetting gain of each channel (CameraModel::VignettingGain)
//     and Gaussian sensor noise from a hash of (seed, frame, pixel, channel),
//     then 8-bit quantisation, as a camera's ADC does.
// The result is read back with rows top to bottom, matching core::ImageRgb8.

namespace pirouette::sim {
namespace {

constexpr double kNear = 0.005;  // metres
constexpr double kFar = 100.0;
constexpr int kFloorTextureSize = 512;
constexpr double kFloorTexelM = 0.003;  // the floor texture's grain
constexpr int kWantedSamples = 4;       // MSAA samples for pass 1
// Pass 1 is a pinhole image, which cannot reach 90° off the axis: a wide lens's
// (rational_polynomial, equidistant) rays up to this angle are rendered, those
// beyond it left black, as outside a fisheye's image circle. Pass 1 grows as
// tan² of it: 80° keeps it under about 12 × 12 times the focal length.
constexpr double kMaxPinholeAngleRad = 80.0 * std::numbers::pi / 180.0;

constexpr const char* kSceneVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 colour;
layout(location = 3) in float textured;
uniform mat4 clip_T_world;
out vec3 v_position;
flat out vec3 v_normal;
flat out vec3 v_colour;
flat out float v_textured;
void main() {
  gl_Position = clip_T_world * vec4(position, 1.0);
  v_position = position;
  v_normal = normal;
  v_colour = colour;
  v_textured = textured;
}
)";

constexpr const char* kSceneFragmentShader = R"(#version 330 core
in vec3 v_position;
flat in vec3 v_normal;
flat in vec3 v_colour;
flat in float v_textured;
uniform vec3 light_towards;  // unit vector towards the light
uniform float ambient;
uniform float intensity;
uniform float texture_amplitude;
uniform float texel_m;
uniform sampler2D floor_noise;  // values in [0, 1], mean 0.5
out vec4 radiance;
void main() {
  float shade = ambient + intensity * max(0.0, dot(v_normal, light_towards));
  vec3 albedo = v_colour;
  if (v_textured > 0.5) {
    vec3 n = texture(floor_noise, v_position.xy / (texel_m * float(textureSize(floor_noise, 0).x))).rgb;
    albedo *= 1.0 + texture_amplitude * (2.0 * n - 1.0);
  }
  radiance = vec4(albedo * shade, 1.0);
}
)";

constexpr const char* kWarpVertexShader = R"(#version 330 core
void main() {
  // One triangle that covers the viewport.
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(2.0 * p - 1.0, 0.0, 1.0);
}
)";

constexpr const char* kWarpFragmentShader = R"(#version 330 core
uniform sampler2D scene;      // pass 1, linear filtering
uniform sampler2D warp;       // RG32F: pass-1 texture coordinates of each output pixel
uniform vec2 principal_point; // cx, cy in pixels
uniform float inv_r_max_squared;
uniform vec3 vignetting_k;
uniform float noise_sigma;    // in 0..255 units
uniform uint seed_lo;
uniform uint seed_hi;
uniform uint frame;
out vec4 colour;

uint Hash(uint x) {  // a PCG-style integer hash (Jarzynski & Olano 2020)
  uint state = x * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}
float Uniform01(inout uint h) {  // in (0, 1]
  h = Hash(h);
  return (float(h >> 8) + 1.0) / 16777216.0;
}
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);  // p.y is the image row v (rows are not flipped)
  vec2 st = texelFetch(warp, p, 0).xy;
  vec3 light = st.x < 0.0 ? vec3(0.0) : texture(scene, st).rgb;  // s < 0: sees nothing
  vec2 d = vec2(p) - principal_point;
  float rho2 = dot(d, d) * inv_r_max_squared;
  light /= vec3(1.0) + vignetting_k * rho2;
  uint h = Hash(seed_lo ^ Hash(seed_hi ^ Hash(frame ^ Hash(uint(p.x) ^ Hash(uint(p.y))))));
  vec3 noise;
  {
    float r = sqrt(-2.0 * log(Uniform01(h)));
    float a = 6.28318530718 * Uniform01(h);
    noise.xy = r * vec2(cos(a), sin(a));
    r = sqrt(-2.0 * log(Uniform01(h)));
    a = 6.28318530718 * Uniform01(h);
    noise.z = r * cos(a);
  }
  vec3 value = light * 255.0 + noise_sigma * noise;
  colour = vec4(clamp(floor(value + 0.5), 0.0, 255.0) / 255.0, 1.0);
}
)";

GLuint CompileShader(GLenum type, const char* source) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    std::array<char, 4096> log{};
    glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
    glDeleteShader(shader);
    throw RenderError(std::string("OpenGL shader does not compile: ") + log.data());
  }
  return shader;
}

GLuint LinkProgram(const char* vertex, const char* fragment) {
  const GLuint vs = CompileShader(GL_VERTEX_SHADER, vertex);
  const GLuint fs = CompileShader(GL_FRAGMENT_SHADER, fragment);
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    std::array<char, 4096> log{};
    glGetProgramInfoLog(program, static_cast<GLsizei>(log.size()), nullptr, log.data());
    glDeleteProgram(program);
    throw RenderError(std::string("OpenGL program does not link: ") + log.data());
  }
  return program;
}

void CheckFramebuffer(const char* what) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw RenderError(std::string("OpenGL framebuffer for ") + what + " is incomplete (status " +
                      std::to_string(status) + ")");
  }
}

// The pinhole frustum of pass 1 in normalised undistorted coordinates (x
// right, y down, OpenCV's), and for each output pixel where its centre falls
// in that frustum's texture (s right, t up).
struct Frustum {
  double x_min, x_max, y_min, y_max;
};

// Where pixel (u, v)'s ray meets pass 1's image plane (z = 1); nullopt for a
// wide lens's pixel that sees nothing or lies beyond kMaxPinholeAngleRad.
// plumb_bob's pixels all have one, from CameraModel::Undistort.
std::optional<Eigen::Vector2d> PinholePoint(const camera::CameraModel& camera, int u, int v) {
  const auto& k = camera.intrinsics();
  if (camera.distortion().model == camera::Distortion::Model::kPlumbBob) {
    return camera.Undistort({(u - k.cx) / k.fx, (v - k.cy) / k.fy});
  }
  const std::optional<Eigen::Vector3d> ray = camera.SeenRay(Eigen::Vector2d(u, v));
  if (!ray || !(ray->z() > std::cos(kMaxPinholeAngleRad))) return std::nullopt;
  return Eigen::Vector2d(ray->x() / ray->z(), ray->y() / ray->z());
}

Frustum CoveringFrustum(const camera::CameraModel& camera,
                        std::vector<std::optional<Eigen::Vector2d>>* rays) {
  const auto& k = camera.intrinsics();
  Frustum f{std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
            std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest()};
  rays->resize(static_cast<std::size_t>(camera.width()) * camera.height());
  for (int v = 0; v < camera.height(); ++v) {
    for (int u = 0; u < camera.width(); ++u) {
      const std::optional<Eigen::Vector2d> point = PinholePoint(camera, u, v);
      (*rays)[static_cast<std::size_t>(v) * camera.width() + u] = point;
      if (!point) continue;
      const Eigen::Vector2d& n = *point;
      f.x_min = std::min(f.x_min, n.x());
      f.x_max = std::max(f.x_max, n.x());
      f.y_min = std::min(f.y_min, n.y());
      f.y_max = std::max(f.y_max, n.y());
    }
  }
  // A margin of two output pixels so that bilinear lookups stay inside.
  const double mx = 2.0 / k.fx;
  const double my = 2.0 / k.fy;
  return {f.x_min - mx, f.x_max + mx, f.y_min - my, f.y_max + my};
}

// Column-major 4×4 matrices as OpenGL takes them.
using Mat4 = Eigen::Matrix<float, 4, 4, Eigen::ColMajor>;

Mat4 FrustumProjection(const Frustum& f) {
  // glFrustum with l = x_min·n, r = x_max·n, b = -y_max·n, t = -y_min·n:
  // OpenGL's eye y is up, OpenCV's image y is down.
  const double l = f.x_min * kNear;
  const double r = f.x_max * kNear;
  const double b = -f.y_max * kNear;
  const double t = -f.y_min * kNear;
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = 2.0 * kNear / (r - l);
  m(0, 2) = (r + l) / (r - l);
  m(1, 1) = 2.0 * kNear / (t - b);
  m(1, 2) = (t + b) / (t - b);
  m(2, 2) = -(kFar + kNear) / (kFar - kNear);
  m(2, 3) = -2.0 * kFar * kNear / (kFar - kNear);
  m(3, 2) = -1.0;
  return m.cast<float>();
}

}  // namespace

struct Renderer::Impl {
  EglContext egl;
  int width = 0;
  int height = 0;
  int scene_width = 0;
  int scene_height = 0;
  int samples = 0;
  Mat4 projection;
  Eigen::Isometry3d robot_T_camera;
  RenderOptions options;
  std::uint32_t frame = 0;

  GLuint scene_program = 0;
  GLuint warp_program = 0;
  GLuint vao = 0;
  GLuint vbo = 0;
  GLsizei vertex_count = 0;
  GLuint empty_vao = 0;
  GLuint floor_noise = 0;
  GLuint msaa_fbo = 0;
  GLuint msaa_colour = 0;
  GLuint msaa_depth = 0;
  GLuint scene_fbo = 0;
  GLuint scene_texture = 0;
  GLuint warp_texture = 0;
  GLuint out_fbo = 0;
  GLuint out_colour = 0;

  Impl(const World& world, const camera::CameraModel& camera, const RenderOptions& opts)
      : egl(EglContext::Create()), options(opts) {
    width = camera.width();
    height = camera.height();
    robot_T_camera =
        camera.robot_T_camera() * Eigen::AngleAxisd(options.roll_rad, Eigen::Vector3d::UnitZ());
    std::vector<std::optional<Eigen::Vector2d>> rays;
    const Frustum frustum = CoveringFrustum(camera, &rays);
    projection = FrustumProjection(frustum);
    // Pass 1 samples the centre of the image at least as finely as the camera.
    scene_width =
        static_cast<int>(std::ceil((frustum.x_max - frustum.x_min) * camera.intrinsics().fx));
    scene_height =
        static_cast<int>(std::ceil((frustum.y_max - frustum.y_min) * camera.intrinsics().fy));

    scene_program = LinkProgram(kSceneVertexShader, kSceneFragmentShader);
    warp_program = LinkProgram(kWarpVertexShader, kWarpFragmentShader);
    UploadMesh(BuildSceneMesh(world));
    UploadFloorNoise(world);
    CreateTargets();
    UploadWarp(frustum, rays);
    SetConstantUniforms(world, camera);
    if (glGetError() != GL_NO_ERROR) throw RenderError("OpenGL reported an error while setting up");
  }

  ~Impl() {
    egl.MakeCurrent();
    const GLuint textures[] = {floor_noise, scene_texture, warp_texture};
    glDeleteTextures(3, textures);
    const GLuint renderbuffers[] = {msaa_colour, msaa_depth, out_colour};
    glDeleteRenderbuffers(3, renderbuffers);
    const GLuint framebuffers[] = {msaa_fbo, scene_fbo, out_fbo};
    glDeleteFramebuffers(3, framebuffers);
    glDeleteBuffers(1, &vbo);
    const GLuint vaos[] = {vao, empty_vao};
    glDeleteVertexArrays(2, vaos);
    glDeleteProgram(scene_program);
    glDeleteProgram(warp_program);
  }

  void UploadMesh(const std::vector<SceneVertex>& mesh) {
    vertex_count = static_cast<GLsizei>(mesh.size());
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.size() * sizeof(SceneVertex)),
                 mesh.data(), GL_STATIC_DRAW);
    const auto stride = static_cast<GLsizei>(sizeof(SceneVertex));
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<void*>(offsetof(SceneVertex, position)));
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<void*>(offsetof(SceneVertex, normal)));
    glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<void*>(offsetof(SceneVertex, colour)));
    glVertexAttribPointer(3, 1, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<void*>(offsetof(SceneVertex, textured)));
    for (GLuint i = 0; i < 4; ++i) glEnableVertexAttribArray(i);
    glGenVertexArrays(1, &empty_vao);
  }

  void UploadFloorNoise(const World& world) {
    // The floor's grain belongs to the world, not to a run: seeded by the
    // world's name so that every run sees the same floor.
    std::seed_seq seq(world.name().begin(), world.name().end());
    std::mt19937 rng(seq);
    std::uniform_int_distribution<int> byte(0, 255);
    std::vector<std::uint8_t> texels(static_cast<std::size_t>(kFloorTextureSize) *
                                     kFloorTextureSize * 3);
    for (auto& t : texels) t = static_cast<std::uint8_t>(byte(rng));
    glGenTextures(1, &floor_noise);
    glBindTexture(GL_TEXTURE_2D, floor_noise);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, kFloorTextureSize, kFloorTextureSize, 0, GL_RGB,
                 GL_UNSIGNED_BYTE, texels.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  }

  void CreateTargets() {
    GLint max_samples = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    samples = std::min(kWantedSamples, static_cast<int>(max_samples));

    glGenRenderbuffers(1, &msaa_colour);
    glBindRenderbuffer(GL_RENDERBUFFER, msaa_colour);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA16F, scene_width,
                                     scene_height);
    glGenRenderbuffers(1, &msaa_depth);
    glBindRenderbuffer(GL_RENDERBUFFER, msaa_depth);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, scene_width,
                                     scene_height);
    glGenFramebuffers(1, &msaa_fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msaa_colour);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msaa_depth);
    CheckFramebuffer("the scene (multisampled)");

    glGenTextures(1, &scene_texture);
    glBindTexture(GL_TEXTURE_2D, scene_texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, scene_width, scene_height, 0, GL_RGBA, GL_FLOAT,
                 nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glGenFramebuffers(1, &scene_fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, scene_fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, scene_texture, 0);
    CheckFramebuffer("the scene (resolved)");

    glGenRenderbuffers(1, &out_colour);
    glBindRenderbuffer(GL_RENDERBUFFER, out_colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glGenFramebuffers(1, &out_fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, out_fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, out_colour);
    CheckFramebuffer("the camera image");
  }

  // A pixel that sees nothing gets s = -1: the warp pass makes it black.
  void UploadWarp(const Frustum& f, const std::vector<std::optional<Eigen::Vector2d>>& rays) {
    std::vector<float> st(rays.size() * 2, -1.0f);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      if (!rays[i]) continue;
      st[2 * i] = static_cast<float>((rays[i]->x() - f.x_min) / (f.x_max - f.x_min));
      st[2 * i + 1] = static_cast<float>((f.y_max - rays[i]->y()) / (f.y_max - f.y_min));
    }
    glGenTextures(1, &warp_texture);
    glBindTexture(GL_TEXTURE_2D, warp_texture);
    // Row v of the image is the texture's row v: the warp pass writes row v
    // of its target, which glReadPixels returns v-th.
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, width, height, 0, GL_RG, GL_FLOAT, st.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }

  void SetConstantUniforms(const World& world, const camera::CameraModel& camera) {
    glUseProgram(scene_program);
    const Eigen::Vector3f towards = (-world.light().direction).normalized().cast<float>();
    glUniform3f(glGetUniformLocation(scene_program, "light_towards"), towards.x(), towards.y(),
                towards.z());
    glUniform1f(glGetUniformLocation(scene_program, "ambient"),
                static_cast<float>(world.light().ambient));
    glUniform1f(glGetUniformLocation(scene_program, "intensity"),
                static_cast<float>(world.light().intensity));
    glUniform1f(glGetUniformLocation(scene_program, "texture_amplitude"),
                static_cast<float>(world.floor().texture));
    glUniform1f(glGetUniformLocation(scene_program, "texel_m"), static_cast<float>(kFloorTexelM));
    glUniform1i(glGetUniformLocation(scene_program, "floor_noise"), 0);

    glUseProgram(warp_program);
    glUniform1i(glGetUniformLocation(warp_program, "scene"), 0);
    glUniform1i(glGetUniformLocation(warp_program, "warp"), 1);
    const auto& k = camera.intrinsics();
    glUniform2f(glGetUniformLocation(warp_program, "principal_point"), static_cast<float>(k.cx),
                static_cast<float>(k.cy));
    glUniform1f(glGetUniformLocation(warp_program, "inv_r_max_squared"),
                static_cast<float>(1.0 / camera.vignetting_r_max_squared()));
    const auto& vk = camera.vignetting().k;
    glUniform3f(glGetUniformLocation(warp_program, "vignetting_k"), static_cast<float>(vk[0]),
                static_cast<float>(vk[1]), static_cast<float>(vk[2]));
    glUniform1f(glGetUniformLocation(warp_program, "noise_sigma"),
                static_cast<float>(options.noise_sigma));
    glUniform1ui(glGetUniformLocation(warp_program, "seed_lo"),
                 static_cast<GLuint>(options.seed & 0xffffffffu));
    glUniform1ui(glGetUniformLocation(warp_program, "seed_hi"),
                 static_cast<GLuint>(options.seed >> 32));
  }

  core::ImageRgb8 Render(const core::Pose2& world_T_robot) {
    egl.MakeCurrent();
    Eigen::Isometry3d world_T_robot3 = Eigen::Isometry3d::Identity();
    world_T_robot3.linear() =
        Eigen::AngleAxisd(world_T_robot.heading(), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    world_T_robot3.translation() = Eigen::Vector3d(world_T_robot.x(), world_T_robot.y(), 0.0);
    const Eigen::Isometry3d camera_T_world = (world_T_robot3 * robot_T_camera).inverse();
    Eigen::Matrix4d gl_T_cv = Eigen::Matrix4d::Identity();
    gl_T_cv(1, 1) = -1.0;
    gl_T_cv(2, 2) = -1.0;
    const Mat4 clip_T_world = projection * (gl_T_cv * camera_T_world.matrix()).cast<float>();

    // Pass 1: the scene.
    glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo);
    glViewport(0, 0, scene_width, scene_height);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_MULTISAMPLE);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(scene_program);
    glUniformMatrix4fv(glGetUniformLocation(scene_program, "clip_T_world"), 1, GL_FALSE,
                       clip_T_world.data());
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, floor_noise);
    glBindVertexArray(vao);
    glDrawArrays(GL_TRIANGLES, 0, vertex_count);

    glBindFramebuffer(GL_READ_FRAMEBUFFER, msaa_fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, scene_fbo);
    glBlitFramebuffer(0, 0, scene_width, scene_height, 0, 0, scene_width, scene_height,
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);

    // Pass 2: lens, vignetting, noise.
    glBindFramebuffer(GL_FRAMEBUFFER, out_fbo);
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(warp_program);
    glUniform1ui(glGetUniformLocation(warp_program, "frame"), frame++);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, scene_texture);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, warp_texture);
    glBindVertexArray(empty_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    core::ImageRgb8 image(width, height);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, image.data());
    if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
      throw RenderError("OpenGL error " + std::to_string(error) + " while rendering a frame");
    }
    return image;
  }
};

Renderer::Renderer(const World& world, const camera::CameraModel& camera,
                   const RenderOptions& options)
    : impl_(std::make_unique<Impl>(world, camera, options)) {}

Renderer::~Renderer() = default;

core::ImageRgb8 Renderer::Render(const core::Pose2& world_T_robot) {
  return impl_->Render(world_T_robot);
}

const std::string& Renderer::gl_renderer() const { return impl_->egl.renderer_name(); }

}  // namespace pirouette::sim
