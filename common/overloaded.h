#pragma once
// A visitor of one lambda per alternative: std::visit(Overloaded{[](A) {}, [](B) {}}, v).
namespace grotto {

template <class... F>
struct Overloaded : F... {
    using F::operator()...;
};

}  // namespace grotto
