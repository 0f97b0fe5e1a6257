// The tsis library: everything of the public API (include/tsis/).
#pragma once

#include "tsis/compare.h"
#include "tsis/error.h"
#include "tsis/options.h"
#include "tsis/render_settings.h"
#include "tsis/renderer.h"
#include "tsis/scene.h"
