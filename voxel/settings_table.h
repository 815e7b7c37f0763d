#pragma once
// One table of the lighting, AO and detail settings. A row is one setting: its
// dotted key (the world file's blocks and field, and a viewer script's name for
// it), its command-line flag, where it lives, its range, help, manifest key and
// what a change of it makes stale. The world-file reader and writer, the flags
// and their --help, validation, the viewer's panel, manifests and the limits test
// all walk these rows. Plain data: no Vulkan, no OpenVDB.
#include "voxel/ao_values.h"
#include "voxel/world_desc.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

namespace grotto::voxel {

enum class SettingType {
    Number,     // a finite number in [lo, hi]
    Whole,      // a whole number in [lo, hi]
    Bool,       // true or false
    Choice,     // one of `choices`
    Color,      // three numbers, each in [lo, hi]
    Direction,  // three numbers, each in [lo, hi], not all zero; kept normalised
};

// Where a setting lives in a world's description (AO: unset = the preset's).
using DescMember = std::variant<std::string AoDesc::*, std::optional<double> AoDesc::*, std::optional<int> AoDesc::*,
                                std::optional<bool> AoDesc::*, float Lighting::*, bool Lighting::*,
                                glm::vec3 Lighting::*, ToneMap Lighting::*, AmbientSource Lighting::*, SunSource Lighting::*,
                                double Detail::*,
                                bool Detail::*>;
// Where an AO setting lives among the settings in effect; none for method and
// quality (they choose the estimator and preset) and for lighting and detail.
using AoMember = std::variant<std::monostate, float EstimatorSettings::*, uint32_t EstimatorSettings::*,
                              float ChainSettings::*, uint32_t ChainSettings::*, bool ChainSettings::*>;

struct Setting {
    std::string_view key;   // "ao.thin_occluder": block and field in a world file; a script's name
    std::string_view flag;  // "--thin-occluder"; empty: none
    SettingType type;
    DescMember desc;
    AoMember value = {};
    double lo = 0.0, hi = 0.0;      // accepted in a world file, on the command line and in scripts
    double uiLo = 0.0, uiHi = 0.0;  // the panel's slider where [lo, hi] is too wide for one; 0, 0: [lo, hi]
    std::string_view help;          // what it does (--help, the panel, docs)
    std::string_view accepted = {};     // the range as errors state it; empty: "lo to hi"
    std::string_view defaultNote = {};  // the default where it depends on the world or preset
    std::string_view manifest = {};     // its key in manifests and stability baselines; empty: none
    std::span<const std::string_view> choices = {};
    bool presetShaped = false;  // the quality preset sets it: naming a preset replaces it
    bool tracingOnly = false;   // only the methods that trace voxels use it
    bool vbaoOnly = false;      // only VBAO uses it
    bool uiRelative = false;    // the panel's range is uiLo to uiHi times the value in effect
};

// Does the AO method named `method` use the setting (the panel shows it, a
// manifest records it)? Every setting but the tracing methods' and VBAO's own;
// of the AO block, the face cache uses only the method, radius, strength and
// cache_rays (which no other method uses).
bool usedBy(const Setting& s, std::string_view method);

// Every setting: lighting, AO, detail, in world-file order.
std::span<const Setting> settingsTable();
// The row of a dotted key; nullptr when there is none.
const Setting* findSetting(std::string_view key);
// The row of a key the code names; a missing one is a programming error (throws).
const Setting& setting(std::string_view key);

// "0 to 0.7", or the row's own text, or the choices: "filmic, linear".
std::string acceptedText(const Setting& s);
// The key's last part, words spaced: "thin occluder"; with the block inside
// lighting ("sun angle") and in AO ("AO method") where it names a choice.
std::string settingLabel(const Setting& s);
// The default as help states it: "0.2", "gtao", "4 voxels".
std::string defaultText(const Setting& s);
// The panel's range: [uiLo, uiHi] where set, else [lo, hi].
std::pair<double, double> uiRange(const Setting& s);

// A setting's value in effect as a number: an AO setting from `estimator` and
// `chain`, the rest from `desc` (bools as 0 or 1). Number, Whole and Bool only.
double settingNumber(const Setting& s, const WorldDesc& desc, const EstimatorSettings& estimator,
                     const ChainSettings& chain);

// Forgets the AO settings a quality preset sets (slices, steps, rays): a preset
// named later replaces them.
void resetPresetShaped(AoDesc& ao);
// The AO settings `over` sets, over those of `ao`.
void overlayAo(const AoDesc& over, AoDesc& ao);

}  // namespace grotto::voxel
