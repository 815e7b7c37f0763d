#pragma once
// A Vulkan device someone else made (a game's own): the public type, its
// requirements stated where the game reads them (grotto/vulkan.h).
#include "grotto/vulkan.h"

namespace grotto::vk {

using ExternalDevice = grotto::VulkanDevice;

}  // namespace grotto::vk
