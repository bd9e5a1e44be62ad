#include "trace.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstring>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/geometric.hpp>

#include "draw.hpp"
#include "hashed_random.hpp"
#include "image.hpp"
#include "mesh/bounds.hpp"
#include "mesh/tangents.hpp"
#include "parallel.hpp"
#include "texture.hpp"

namespace knitc::render {

namespace {

constexpr int max_side = 16384;
constexpr float inf = std::numeric_limits<float>::infinity();

// Light, linear RGB, fixed to the camera (x right, y up, z toward the viewer).
const glm::vec3 key_direction = glm::normalize(glm::vec3(-0.45f, 0.55f, 0.70f));
constexpr float key_radiance = 0.80f;
constexpr float key_radius = 0.14f;  // the disc's angular radius, ~8 degrees: soft shadows
constexpr float sky_radiance = 0.40f;
constexpr float sheen_strength = 0.35f;
// A fibre lets this share of the light that meets it through (keratin and cellulose are
// translucent): shadow and sky rays, and the camera's, pass a fibre at random this often,
// so a halo is a haze and fibres shade each other partly, averaged over the samples.
constexpr float fibre_passes = 0.45f;
constexpr float half_field_of_view = 10.0f * std::numbers::pi_v<float> / 180.0f;

using hashed::mix;
float uniform(std::uint64_t stream, std::uint32_t dimension) { return static_cast<float>(hashed::uniform(stream, dimension)); }

struct Device {
  RTCDevice device = nullptr;
  std::string error;
  explicit Device(int threads) {
    const std::string config = "threads=" + std::to_string(threads) + ",verbose=0";
    device = rtcNewDevice(config.c_str());
    if (device == nullptr) throw std::runtime_error("render: Embree cannot start a device");
    rtcSetDeviceErrorFunction(
        device, [](void* user, RTCError, const char* message) { static_cast<Device*>(user)->error = message ? message : "error"; },
        this);
  }
  ~Device() { rtcReleaseDevice(device); }
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;
  void check(const char* doing) const {
    if (!error.empty()) throw std::runtime_error(std::string("render: Embree failed ") + doing + ": " + error);
  }
};

struct Scene {
  RTCScene scene = nullptr;
  explicit Scene(RTCDevice device) : scene(rtcNewScene(device)) {}
  ~Scene() {
    if (scene) rtcReleaseScene(scene);
  }
  Scene(Scene&& o) noexcept : scene(o.scene) { o.scene = nullptr; }
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;
  Scene& operator=(Scene&&) = delete;
};

// Whether a ray passes the fibre it met: a hash of the ray and the fibre's segment, so the
// same ray decides the same way whatever the thread or the order Embree meets the hits in.
void fibre_filter(const RTCFilterFunctionNArguments* args) {
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    std::uint64_t key = RTCHitN_primID(args->hit, args->N, i);
    for (const float x : {RTCRayN_org_x(args->ray, args->N, i), RTCRayN_org_y(args->ray, args->N, i), RTCRayN_org_z(args->ray, args->N, i),
                          RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i), RTCRayN_dir_z(args->ray, args->N, i)}) {
      std::uint32_t bits = 0;
      std::memcpy(&bits, &x, sizeof bits);
      key = mix(key ^ bits);
    }
    if (hashed::uniform(key, 0) < fibre_passes) args->valid[i] = 0;
  }
}

// Each triangle primitive of `primitives` attached to `scene`; returns the primitive of each
// geometry id.
// A line primitive's segments as Embree's round linear curves: each segment's two ends
// (position and radius) copied, so segment i is curve i.
void attach_fibres(RTCDevice device, RTCScene scene, const mesh::Primitive& p, std::vector<const mesh::Primitive*>& of_id) {
  const bool strip = p.mode == mesh::Mode::line_strip;
  const std::size_t segments = strip ? (p.indices.size() < 2 ? 0 : p.indices.size() - 1) : p.indices.size() / 2;
  if (segments == 0) return;
  RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 2 * segments));
  auto* first = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(unsigned), segments));
  if (v == nullptr || first == nullptr) {
    rtcReleaseGeometry(g);
    throw std::runtime_error("render: Embree cannot hold the fibres (out of memory)");
  }
  for (std::size_t i = 0; i < segments; ++i) {
    const std::uint32_t ends[2] = {p.indices[strip ? i : 2 * i], p.indices[strip ? i + 1 : 2 * i + 1]};
    for (int e = 0; e < 2; ++e) {
      const glm::vec3& at = p.positions[ends[e]];
      float* out = v + 4 * (2 * i + static_cast<std::size_t>(e));
      out[0] = at.x, out[1] = at.y, out[2] = at.z, out[3] = p.line_radius;
    }
    first[i] = static_cast<unsigned>(2 * i);
  }
  rtcSetGeometryIntersectFilterFunction(g, fibre_filter);
  rtcSetGeometryOccludedFilterFunction(g, fibre_filter);
  rtcCommitGeometry(g);
  const unsigned id = rtcAttachGeometry(scene, g);
  rtcReleaseGeometry(g);
  if (id >= of_id.size()) of_id.resize(id + 1, nullptr);
  of_id[id] = &p;
}

std::vector<const mesh::Primitive*> attach(RTCDevice device, RTCScene scene, const std::vector<mesh::Primitive>& primitives) {
  std::vector<const mesh::Primitive*> of_id;
  for (const mesh::Primitive& p : primitives) {
    if (p.mode != mesh::Mode::triangles && p.line_radius > 0.0f && !p.positions.empty()) {
      attach_fibres(device, scene, p, of_id);
      continue;
    }
    if (p.mode != mesh::Mode::triangles || p.indices.size() < 3 || p.positions.empty()) continue;
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree's own buffers: it pads them for its vector loads.
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                          p.positions.size()));
    auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                             p.indices.size() / 3));
    if (v == nullptr || t == nullptr) {
      rtcReleaseGeometry(g);
      throw std::runtime_error("render: Embree cannot hold the mesh (out of memory)");
    }
    for (std::size_t i = 0; i < p.positions.size(); ++i)
      for (int k = 0; k < 3; ++k) v[3 * i + k] = p.positions[i][k];
    std::copy(p.indices.begin(), p.indices.begin() + static_cast<std::ptrdiff_t>(p.indices.size() / 3 * 3), t);
    rtcCommitGeometry(g);
    const unsigned id = rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
    if (id >= of_id.size()) of_id.resize(id + 1, nullptr);
    of_id[id] = &p;
  }
  return of_id;
}

// The mesh as Embree's scene: plain primitives, and each instanced group a scene of its own
// placed once per translation.
struct World {
  Scene top;
  std::vector<Scene> groups;
  std::vector<const mesh::Primitive*> plain;                // top geometry id -> primitive (null: an instance)
  std::vector<int> group_of;                                // top geometry id -> group (-1: plain)
  std::vector<std::vector<const mesh::Primitive*>> inside;  // group -> its geometry id -> primitive
  // The tangents of each primitive a normal map bends (mesh/tangents.hpp), interpolated
  // across a triangle as a viewer's TANGENT is; empty for the others.
  std::map<const mesh::Primitive*, std::vector<glm::vec4>> tangents;
  World(RTCDevice device, const mesh::Mesh& mesh) : top(device) {
    const auto add_tangents = [&](const mesh::Primitive& p) {
      const std::size_t m = static_cast<std::size_t>(p.material);
      if (p.mode == mesh::Mode::triangles && !p.normals.empty() && !p.uvs.empty() && m < mesh.materials.size() &&
          mesh.materials[m].textures.normal >= 0)
        tangents[&p] = mesh::vertex_tangents(p);
    };
    for (const mesh::Primitive& p : mesh.primitives) add_tangents(p);
    for (const mesh::Instances& group : mesh.instanced)
      for (const mesh::Primitive& p : group.primitives) add_tangents(p);
    rtcSetSceneFlags(top.scene, RTC_SCENE_FLAG_ROBUST);  // no ray slips between two triangles
    plain = attach(device, top.scene, mesh.primitives);
    group_of.assign(plain.size(), -1);
    for (std::size_t gi = 0; gi < mesh.instanced.size(); ++gi) {
      const mesh::Instances& group = mesh.instanced[gi];
      groups.emplace_back(device);
      rtcSetSceneFlags(groups.back().scene, RTC_SCENE_FLAG_ROBUST);
      inside.push_back(attach(device, groups.back().scene, group.primitives));
      rtcCommitScene(groups.back().scene);
      for (const glm::vec3& shift : group.translations) {
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(g, groups.back().scene);
        rtcSetGeometryTimeStepCount(g, 1);
        const float xfm[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, shift.x, shift.y, shift.z};
        rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
        rtcCommitGeometry(g);
        const unsigned id = rtcAttachGeometry(top.scene, g);
        rtcReleaseGeometry(g);
        if (id >= plain.size()) plain.resize(id + 1, nullptr), group_of.resize(id + 1, -1);
        group_of[id] = static_cast<int>(gi);
      }
    }
    rtcCommitScene(top.scene);
  }
};

struct View {
  glm::vec3 eye, forward, right, up;
  float half_w = 1.0f, half_h = 1.0f;  // the image plane at distance 1
};

View look(const mesh::Bounds& box, bool from_back, float aspect, double close_up) {
  const glm::vec3 lo = box.empty ? glm::vec3(-5.0f) : box.min;
  const glm::vec3 hi = box.empty ? glm::vec3(5.0f) : box.max;
  const glm::vec3 centre = 0.5f * (lo + hi), size = hi - lo;
  float half_x, half_y;
  if (close_up > 0.0) {
    half_x = half_y = 0.5f * static_cast<float>(close_up);
  } else {
    const float margin = 0.04f * std::max({size.x, size.y, 1e-3f});
    half_x = 0.5f * std::max(size.x, 1e-3f) + margin;
    half_y = 0.5f * std::max(size.y, 1e-3f) + margin;
  }
  const float t = std::tan(half_field_of_view);
  // From the nearest face of the box, far enough that the extent fits the field of view.
  const float distance = std::max(half_y / t, half_x / (t * aspect)) + 0.5f * std::max(size.z, 1e-3f);
  View v;
  v.forward = glm::vec3(0.0f, 0.0f, from_back ? 1.0f : -1.0f);
  v.up = glm::vec3(0.0f, 1.0f, 0.0f);
  v.right = glm::vec3(from_back ? -1.0f : 1.0f, 0.0f, 0.0f);
  v.eye = centre - distance * v.forward;
  v.half_h = t;
  v.half_w = t * aspect;
  return v;
}

struct Shader {
  RTCScene scene;
  const World& world;
  const mesh::Mesh& mesh;
  const View& view;
  glm::vec3 background;
  glm::vec3 key, key_u, key_v;  // world: towards the key light, and the disc's axes

  // Whether anything lies along `dir` from `from`, past `near`.
  bool occluded(const glm::vec3& from, const glm::vec3& dir, float near = 0.0f) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    ray.org_x = from.x, ray.org_y = from.y, ray.org_z = from.z;
    ray.dir_x = dir.x, ray.dir_y = dir.y, ray.dir_z = dir.z;
    ray.tnear = near;
    ray.tfar = inf;
    ray.mask = 0xffffffffu;
    rtcOccluded1(scene, &context, &ray);
    return ray.tfar < 0.0f;
  }

  // One sample of the pixel through image-plane point (sx, sy) in [-1, 1].
  glm::vec3 sample(float sx, float sy, std::uint64_t stream) const {
    const glm::vec3 dir = glm::normalize(view.forward + sx * view.half_w * view.right + sy * view.half_h * view.up);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = view.eye.x, rh.ray.org_y = view.eye.y, rh.ray.org_z = view.eye.z;
    rh.ray.dir_x = dir.x, rh.ray.dir_y = dir.y, rh.ray.dir_z = dir.z;
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = inf;
    rh.ray.mask = 0xffffffffu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return background;

    const mesh::Primitive* p = nullptr;
    if (rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID)
      p = world.inside[static_cast<std::size_t>(world.group_of[rh.hit.instID[0]])][rh.hit.geomID];
    else
      p = world.plain[rh.hit.geomID];
    glm::vec3 ng(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
    const float ng_length = glm::length(ng);
    ng = ng_length > 1e-20f ? ng / ng_length : -dir;  // a degenerate hit faces the viewer
    if (glm::dot(ng, dir) > 0.0f) ng = -ng;
    glm::vec3 n = ng;
    const mesh::Material& m = mesh.materials[static_cast<std::size_t>(p->material)];
    glm::vec3 albedo = m.base_color;
    float occlusion = 1.0f;  // the occlusion map's: the sky a point of the yarn's surface sees
    const std::size_t prim = rh.hit.primID;
    if (p->mode == mesh::Mode::triangles) {
      const std::uint32_t i0 = p->indices[3 * prim], i1 = p->indices[3 * prim + 1], i2 = p->indices[3 * prim + 2];
      const float u = rh.hit.u, v = rh.hit.v, w = 1.0f - u - v;
      if (!p->normals.empty()) {
        const glm::vec3 s = w * p->normals[i0] + u * p->normals[i1] + v * p->normals[i2];
        if (glm::dot(s, s) > 1e-12f) n = glm::normalize(s);
        const mesh::Textures& maps = m.textures;
        if (maps.any() && !p->uvs.empty()) {
          // The baked yarn's maps, at the hit's texture coordinate on the repeated tile.
          const glm::vec2 st = (w * p->uvs[i0] + u * p->uvs[i1] + v * p->uvs[i2]) / maps.repeat;
          if (const auto found = world.tangents.find(p); maps.normal >= 0 && found != world.tangents.end()) {
            const std::vector<glm::vec4>& ts = found->second;
            const glm::vec4 t = w * ts[i0] + u * ts[i1] + v * ts[i2];
            glm::vec3 tangent = glm::vec3(t) - n * glm::dot(n, glm::vec3(t));
            tangent = glm::dot(tangent, tangent) > 1e-12f ? glm::normalize(tangent) : glm::vec3(ts[i0]);
            const glm::vec3 local = 2.0f * texel(mesh.images[static_cast<std::size_t>(maps.normal)], st) - 1.0f;
            const glm::vec3 bitangent = glm::cross(n, tangent) * (t.w < 0.0f ? -1.0f : 1.0f);
            const glm::vec3 bent = local.x * tangent + local.y * bitangent + local.z * n;
            if (glm::dot(bent, bent) > 1e-12f) n = glm::normalize(bent);
          }
          if (maps.occlusion >= 0) occlusion = texel(mesh.images[static_cast<std::size_t>(maps.occlusion)], st).r;
          if (maps.colour >= 0) albedo *= linear_from_srgb(texel(mesh.images[static_cast<std::size_t>(maps.colour)], st));
        }
        if (glm::dot(n, dir) > 0.0f) n = -n;  // toward the viewer, keeping its slant
      }
      if (!p->colors.empty()) albedo *= w * p->colors[i0] + u * p->colors[i1] + v * p->colors[i2];
    }
    glm::vec3 along{0.0f};  // a fibre's direction
    if (p->mode != mesh::Mode::triangles) {  // a fibre: its segment's two ends
      const bool strip = p->mode == mesh::Mode::line_strip;
      const std::uint32_t a = p->indices[strip ? prim : 2 * prim], b = p->indices[strip ? prim + 1 : 2 * prim + 1];
      if (!p->colors.empty()) albedo *= glm::mix(p->colors[a], p->colors[b], rh.hit.u);
      const glm::vec3 d = p->positions[b] - p->positions[a];
      if (glm::dot(d, d) > 1e-20f) along = glm::normalize(d);
    }

    const glm::vec3 hit = view.eye + rh.ray.tfar * dir;
    // Off the surface before the shadow and sky rays leave; off a fibre by its width, so
    // they do not meet the fibre they start on.
    const float lift = 1e-4f * (1.0f + glm::length(hit)) + (p->mode == mesh::Mode::triangles ? 0.0f : 2.5f * p->line_radius);
    const glm::vec3 from = hit + ng * lift;

    // The key light: a point on its disc, one shadow ray.
    const float r = key_radius * std::sqrt(uniform(stream, 2)), phi = 2.0f * std::numbers::pi_v<float> * uniform(stream, 3);
    const glm::vec3 to_key = glm::normalize(key + r * std::cos(phi) * key_u + r * std::sin(phi) * key_v);
    float direct = 0.0f;
    if (along != glm::vec3(0.0f)) {
      // A thin translucent fibre is lit from any side by how square it lies to the light
      // (Kajiya and Kay's diffuse term), not by the side of it the camera sees.
      const float c = glm::dot(along, to_key);
      // The shadow ray leaves from the fibre's axis, past its own width (the light may lie behind it).
      if (!occluded(hit, to_key, lift)) direct = key_radiance * std::sqrt(std::max(0.0f, 1.0f - c * c));
    } else if (const float c = glm::dot(n, to_key); c > 0.0f && glm::dot(ng, to_key) > 0.0f && !occluded(from, to_key)) {
      direct = key_radiance * c;
    }

    // The sky: one cosine-weighted direction about the normal; open sky scores 1.
    const float r2 = std::sqrt(uniform(stream, 4)), phi2 = 2.0f * std::numbers::pi_v<float> * uniform(stream, 5);
    const glm::vec3 a = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 tu = glm::normalize(glm::cross(n, a)), tv = glm::cross(n, tu);
    const glm::vec3 to_sky =
        r2 * std::cos(phi2) * tu + r2 * std::sin(phi2) * tv + std::sqrt(std::max(0.0f, 1.0f - r2 * r2)) * n;
    const float open = glm::dot(ng, to_sky) > 0.0f && !occluded(from, to_sky) ? 1.0f : 0.0f;

    // Fibres' sheen: a rim toward grazing angles where the sky reaches.
    const float facing = std::clamp(-glm::dot(n, dir), 0.0f, 1.0f);
    const float rim = sheen_strength * std::pow(1.0f - facing, 4.0f) * open;
    return albedo * (direct + sky_radiance * open * occlusion) + m.sheen_color * rim * occlusion;
  }
};

}  // namespace

std::string traced_png(const mesh::Mesh& mesh, const TraceOptions& options) {
  const int w = options.width, h = options.height;
  if (w < 1 || h < 1 || w > max_side || h > max_side)
    throw std::runtime_error("render: image size " + std::to_string(w) + " x " + std::to_string(h) + " is not within 1 to " +
                             std::to_string(max_side) + " pixels a side");
  const bool both = options.side == TraceOptions::Side::both;
  if (both && 2 * w > max_side)
    throw std::runtime_error("render: two views of width " + std::to_string(w) + " are wider than " + std::to_string(max_side) +
                             " pixels");
  if (options.samples < 1 || options.samples > 1024)
    throw std::runtime_error("render: " + std::to_string(options.samples) + " samples a pixel is not within 1 to 1024");
  if (!(options.close_up >= 0.0) || !std::isfinite(options.close_up))
    throw std::runtime_error("render: a close-up's width must be a finite length of 0 mm or more");
  detail::validate(mesh);

  const int threads = thread_count(options.threads);
  Device device(threads);
  const World world(device.device, mesh);
  device.check("building the scene");
  const mesh::Bounds box = mesh::bounds(mesh);
  const float aspect = static_cast<float>(w) / static_cast<float>(h);

  detail::Image image;
  image.width = both ? 2 * w : w;
  image.height = h;
  image.rgb.assign(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(h) * 3, 0);
  int grid = 1;
  while (grid * grid < options.samples) ++grid;

  const auto draw_view = [&](bool from_back, int x0) {
    const View view = look(box, from_back, aspect, options.close_up);
    const glm::vec3 back = -view.forward;
    const glm::vec3 key = glm::normalize(key_direction.x * view.right + key_direction.y * view.up + key_direction.z * back);
    const glm::vec3 key_u = glm::normalize(glm::cross(key, view.up));
    const Shader shader{world.top.scene, world, mesh, view, options.background, key, key_u, glm::cross(key, key_u)};
    const std::uint64_t side_seed = mix(options.seed * 2 + (from_back ? 1 : 0));
    parallel_for(static_cast<std::size_t>(h), threads, [&](std::size_t row) {
      const int y = static_cast<int>(row);
      for (int x = 0; x < w; ++x) {
        glm::dvec3 sum{0.0};
        const std::uint64_t pixel = mix(side_seed ^ mix((static_cast<std::uint64_t>(y) << 32) | static_cast<std::uint32_t>(x)));
        for (int s = 0; s < options.samples; ++s) {
          const std::uint64_t stream = mix(pixel + static_cast<std::uint64_t>(s));
          // Stratified: sample s in cell s of a grid x grid pattern, jittered within it.
          const float fx = (static_cast<float>(s % grid) + uniform(stream, 0)) / static_cast<float>(grid);
          const float fy = (static_cast<float>(s / grid % grid) + uniform(stream, 1)) / static_cast<float>(grid);
          const float sx = 2.0f * (static_cast<float>(x) + fx) / static_cast<float>(w) - 1.0f;
          const float sy = 1.0f - 2.0f * (static_cast<float>(y) + fy) / static_cast<float>(h);
          sum += glm::dvec3(shader.sample(sx, sy, stream));
        }
        const glm::dvec3 mean = sum / static_cast<double>(options.samples);
        std::uint8_t* out = &image.rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                                        static_cast<std::size_t>(x0 + x)) * 3];
        for (int k = 0; k < 3; ++k) out[k] = detail::srgb8(static_cast<float>(mean[k]));
      }
    });
  };
  switch (options.side) {
    case TraceOptions::Side::face: draw_view(false, 0); break;
    case TraceOptions::Side::back: draw_view(true, 0); break;
    case TraceOptions::Side::both:
      draw_view(false, 0);
      draw_view(true, w);
      break;
  }
  device.check("tracing rays");
  return detail::encode_png(image);
}

glm::vec2 traced_pixel(const mesh::Bounds& box, const TraceOptions& options, bool from_back, glm::vec3 point) {
  const float aspect = static_cast<float>(options.width) / static_cast<float>(options.height);
  const View view = look(box, from_back, aspect, options.close_up);
  const glm::vec3 d = point - view.eye;
  const float depth = glm::dot(d, view.forward);
  if (depth <= 0.0f) return glm::vec2(-1.0f);
  const float sx = glm::dot(d, view.right) / (depth * view.half_w), sy = glm::dot(d, view.up) / (depth * view.half_h);
  return {0.5f * (sx + 1.0f) * static_cast<float>(options.width), 0.5f * (1.0f - sy) * static_cast<float>(options.height)};
}

}  // namespace knitc::render
