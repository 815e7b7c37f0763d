#pragma once
// The viewer's Dear ImGui panel: AO and lighting settings, the view, named
// cameras, per-pass timings and world counts. It changes settings the way a
// script does: as a patch of world-file keys (voxel::applySettingsPatch).
#include "engine/renderer.h"
#include "voxel/json_reader.h"
#include "voxel/world_desc.h"

#include <deque>
#include <string>
#include <vector>

namespace grotto::viewer {

// The views the panel offers: the final image, or one AOV (showAov's names).
// "light" is the face cache's (black with other AO methods).
inline const std::vector<std::string> kViews = {"final",  "ao",    "raw",    "spatial", "temporal", "history",
                                                "edges", "normal", "depth", "shadow",  "light"};

struct PanelState {
    const voxel::WorldDesc* desc = nullptr;  // the settings now, as the world file writes them
    const AoOptions* ao = nullptr;           // the AO settings in effect
    std::string view = "final";
    bool hidden = false;                     // Tab hides the panel
    double renderScale = 1.0;                // frame pixels per window pixel
    std::vector<std::string> cameras;        // the world's named cameras
    std::string jumpTo;                      // set when a camera button was pressed
    std::vector<std::string> paths;          // the world's camera paths
    std::string play;                        // set when a path's play button was pressed
    std::string playing;                     // the path playing now, if any
    bool screenshot = false;                 // set when the screenshot button was pressed
    FrameStats stats;                        // the last frame's
    std::deque<float> frameMs;               // recent frame times, oldest first
    uint64_t quads = 0, activeVoxels = 0;
    double speed = 0.0;                      // fly speed, world units per second
    double lightBaked = 1.0;                 // the world's full light baking on its own thread: 0 to 1
    std::string message;                     // the last error or saved file, shown at the bottom
    // Editing: what a left click does, the brush and the material placed or painted.
    std::string editMode = "none";           // none, dig, place, paint
    double brushRadius = 1.0;                // voxels
    int material = 1;
    bool undo = false, saveWorld = false;    // set when their buttons were pressed
    std::string saveWorldAs;                 // .json (and its .vdb) or .vdb (and its .json)
    // Recording a camera path.
    size_t recordedKeys = 0;
    bool record = false, savePath = false;   // set when their buttons were pressed
    std::string savePathAs;                  // .json
};

// Draws the panel (inside an ImGui frame) and returns the settings it changed as a
// patch ({"lighting": ..., "ao": ...}); empty when nothing changed.
voxel::json drawPanel(PanelState& state);

}  // namespace grotto::viewer
