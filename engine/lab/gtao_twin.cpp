#include "engine/lab/gtao_twin.h"

#include "shaders/shared/quad.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace grotto {
namespace twin {
using namespace glm;
using namespace grotto::gpu;

#include "shaders/shared/vbao_sectors.h"

// The kernel's functions become members; its inputs are the G-buffer copies here.
struct Kernel {
    GtaoConstants gtao;
    std::vector<float> depthBuffer;
    std::vector<uint16_t> surface;
    std::array<std::vector<float>, GROTTO_GTAO_DEPTH_MIPS> mips;
    std::array<ivec2, GROTTO_GTAO_DEPTH_MIPS> mipSize;

    float gtaoDepth(ivec2 texel, int mip) {
        ivec2 t = clamp(texel >> mip, ivec2(0), mipSize[mip] - 1);
        return mips[mip][size_t(t.y) * mipSize[mip].x + t.x];
    }
    uint gtaoSurface(ivec2 p) { return surface[size_t(p.y) * gtao.fullSize.x + p.x]; }
    // VBAO's voxels thickness is traced on the GPU only: the twin runs the other modes.
    float gtaoThickness(ivec2, int) { return 1e30f; }

#include "shaders/shared/gtao_kernel.h"

    // The depth prefilter, as shaders/depth_prefilter.comp does it.
    void buildMips() {
        for (int k = 0; k < GROTTO_GTAO_DEPTH_MIPS; ++k) {
            const int round = (1 << k) - 1;
            mipSize[k] = ivec2((int(gtao.halfSize.x) + round) >> k, (int(gtao.halfSize.y) + round) >> k);
            mips[k].resize(size_t(mipSize[k].x) * mipSize[k].y);
            for (int y = 0; y < mipSize[k].y; ++y)
                for (int x = 0; x < mipSize[k].x; ++x) {
                    float v;
                    if (k == 0) {
                        const float d = depthBuffer[size_t(gtao.scale * y) * gtao.fullSize.x + gtao.scale * x];
                        v = d > 0.0f ? std::min(gtao.depthB / (d + gtao.depthA), kGtaoSky) : kGtaoSky;
                    } else {
                        const ivec2 last = mipSize[k - 1] - 1;
                        auto at = [&](int dx, int dy) {
                            const ivec2 t = min(ivec2(2 * x + dx, 2 * y + dy), last);
                            return mips[k - 1][size_t(t.y) * mipSize[k - 1].x + t.x];
                        };
                        v = gtaoMipFilter(at(0, 0), at(1, 0), at(0, 1), at(1, 1));
                    }
                    mips[k][size_t(y) * mipSize[k].x + x] = v;
                }
        }
    }
};

// VBAO: the same kernel with each slice's bitmask (what vbao.comp compiles).
struct VbaoKernel : Kernel {
    static constexpr bool kVbaoBentNormals = true;
    vec3 bent{0.0f};  // the last pixel's bent normal
    void vbaoBentNormal(ivec2, vec3 direction) { bent = direction; }
#define GROTTO_VBAO
#include "shaders/shared/gtao_kernel.h"
#undef GROTTO_VBAO
};

}  // namespace twin

struct GtaoTwin::Kernel : twin::VbaoKernel {};

GtaoTwin::GtaoTwin(const gpu::GtaoConstants& constants, std::vector<float> depthBuffer, std::vector<uint16_t> surface,
                   bool vbao)
    : kernel_(new Kernel), vbao_(vbao) {
    kernel_->gtao = constants;
    kernel_->depthBuffer = std::move(depthBuffer);
    kernel_->surface = std::move(surface);
    kernel_->buildMips();
}

GtaoTwin::~GtaoTwin() { delete kernel_; }

glm::vec2 GtaoTwin::pixel(glm::ivec2 p) const {
    return vbao_ ? kernel_->VbaoKernel::gtaoPixel(p) : kernel_->twin::Kernel::gtaoPixel(p);
}

glm::vec3 GtaoTwin::bentNormal(glm::ivec2 p) const {
    kernel_->VbaoKernel::gtaoPixel(p);
    return kernel_->bent;
}

}  // namespace grotto
