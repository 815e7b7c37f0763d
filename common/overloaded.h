#pragma once
// A visitor of one lambda per alternative: std::visit(Overloaded{[](A) {}, [](B) {}}, v).
namespace grotto {

template <class... F>
struct Overloaded : F... {
    using F::operator()...;
};
// C++20 deduces this without the guide; clang 14 (the fuzz preset) still needs it.
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

}  // namespace grotto
