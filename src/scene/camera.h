#pragma once
#include <string>

#include "scene/scene.h"

namespace lll {

// The camera a --camera value names: one of the scene's cameras by name, or "ex,ey,ez,tx,ty,tz"
// (eye and target), or "ex,ey,ez,tx,ty,tz,fov" with the vertical field of view in degrees (60
// otherwise). Empty picks the scene's first camera, or a view of the whole scene when it has
// none. Throws InputError for an unknown name or malformed numbers, listing the choices.
Camera resolveCamera(const Scene& scene, const std::string& spec);

// A camera that frames the whole scene from above one corner of its bounds.
Camera overviewCamera(const Bounds& bounds);

}  // namespace lll
