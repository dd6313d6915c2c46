// Flag parsing shared by `rastrace render`, `compare` and `texsweep`: the scene render flags
// (experiments/render_settings.h holds what they mean) and the command-line cache specs.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "cache_sim/cache_config.h"
#include "cache_sim/live_bank_sink.h"
#include "experiments/render_settings.h"

namespace rastrace {

void add_scene_render_flags(CLI::App& command, SceneRenderFlags& flags);
// --aniso 1..16 and --aniso-rule ellipse|probes, for the commands that bind their own render flags.
void add_anisotropy_flags(CLI::App& command, unsigned& aniso, std::string& rule);

// One cache in the cache-spec grammar (cache_sim/cache_spec.h): "entries=16,policy=fifo" and
// "size=16KiB,line=64B,assoc=4,policy=lru,layout=block4".
VertexCacheSpec parse_vcache_spec(const std::string& text);
TextureCacheSpec parse_tcache_spec(const std::string& text);

}  // namespace rastrace
