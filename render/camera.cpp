#include "camera.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace knitc::render::detail {

Camera frame(const Bounds& box, bool from_back, float aspect) {
  // An empty mesh still gets a sensible 10 mm view around the origin.
  const glm::vec3 lo = box.empty ? glm::vec3(-5.0f) : box.min;
  const glm::vec3 hi = box.empty ? glm::vec3(5.0f) : box.max;
  const glm::vec3 centre = 0.5f * (lo + hi);
  const glm::vec3 size = hi - lo;

  // Half extents of the view: the box's XY extent plus a margin, widened on one axis to the
  // frame's aspect. A degenerate box (one point, or a line) still gets a finite view.
  const float largest = std::max({size.x, size.y, 1e-3f});
  const float margin = 0.04f * largest;
  float half_w = 0.5f * std::max(size.x, 1e-3f) + margin;
  float half_h = 0.5f * std::max(size.y, 1e-3f) + margin;
  if (half_w < half_h * aspect) half_w = half_h * aspect;
  else half_h = half_w / aspect;

  // Stand in front of the box by its depth plus a little, so nothing clips at either plane.
  const float depth = std::max(size.z, 1e-3f);
  const float distance = depth + 0.1f * largest + 1.0f;
  const glm::vec3 eye = from_back ? glm::vec3(centre.x, centre.y, lo.z - distance)
                                  : glm::vec3(centre.x, centre.y, hi.z + distance);

  Camera c;
  c.view = glm::lookAt(eye, glm::vec3(centre.x, centre.y, centre.z), glm::vec3(0.0f, 1.0f, 0.0f));
  const float near_plane = 0.5f * distance;
  const float far_plane = distance + depth + 0.5f * distance;
  c.projection = glm::ortho(-half_w, half_w, -half_h, half_h, near_plane, far_plane);
  c.normal = glm::mat3(c.view);
  return c;
}

}  // namespace knitc::render::detail
