#pragma once
// SITE: the site's limits, the intended fall and the protected zones
// (core/Site.h), with the flying fragments' mass and the risk a study must show.
#include "macro/mesh/MeshCommands.h"

namespace c2d {

MeshCommandEntry siteCommandEntry();

}  // namespace c2d
