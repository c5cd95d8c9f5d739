#pragma once
// The analytic scenes' key reference (`kerf-forces keys`, docs/scenes.md) is a list of kerf::SceneKeySection.
#include "kerf/key_sections.hpp"
