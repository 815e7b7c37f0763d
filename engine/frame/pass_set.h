#pragma once
// The passes a frame plan needs, made from it. Each pass type P says
//   static bool runs(const FramePlan&)   when it runs (when it exists);
//   static auto key(const FramePlan&)    what it is made from: a tuple of its
//                                        constructor's arguments after the context
//                                        (a pass without key() takes the context alone).
// update() makes the passes missing, drops those the plan does not run and remakes
// those whose key changed; nothing else makes, resets or frees a pass.
#include "engine/frame/frame_plan.h"
#include "engine/vk/context.h"

#include <memory>
#include <optional>
#include <tuple>
#include <utility>

namespace grotto {

template <class P>
concept KeyedPass = requires(const FramePlan& plan) { P::key(plan); };

template <class P>
auto passKey(const FramePlan& plan) {
    if constexpr (KeyedPass<P>) return P::key(plan);
    else return std::tuple<>{};
}

template <class... Passes>
class PassSet {
public:
    explicit PassSet(vk::Context& ctx) : ctx_(ctx) {}
    PassSet(const PassSet&) = delete;
    PassSet& operator=(const PassSet&) = delete;

    // Whether update(plan) would make, drop or remake any: before, no frame in
    // flight may still use the passes it frees.
    bool changes(const FramePlan& plan) const { return (slot<Passes>().changes(plan) || ...); }
    void update(const FramePlan& plan) { (slot<Passes>().update(ctx_, plan), ...); }
    void release() { (slot<Passes>().pass.reset(), ...); }

    // The pass, where the plan it was updated to runs it.
    template <class P> P& get() const { return *slot<P>().pass; }
    template <class P> P* find() const { return slot<P>().pass.get(); }

private:
    template <class P>
    struct Slot {
        using Key = decltype(passKey<P>(std::declval<const FramePlan&>()));
        std::unique_ptr<P> pass;
        Key key{};

        bool changes(const FramePlan& plan) const {
            if (!P::runs(plan)) return pass != nullptr;
            return !pass || !(key == passKey<P>(plan));
        }
        void update(vk::Context& ctx, const FramePlan& plan) {
            if (!P::runs(plan)) {
                pass.reset();
                return;
            }
            Key wanted = passKey<P>(plan);
            if (pass && key == wanted) return;
            pass.reset();  // before its successor: never two alive at once
            pass = std::apply([&](const auto&... args) { return std::make_unique<P>(ctx, args...); }, wanted);
            key = std::move(wanted);
        }
    };
    template <class P> Slot<P>& slot() { return std::get<Slot<P>>(slots_); }
    template <class P> const Slot<P>& slot() const { return std::get<Slot<P>>(slots_); }

    vk::Context& ctx_;
    std::tuple<Slot<Passes>...> slots_;
};

}  // namespace grotto
