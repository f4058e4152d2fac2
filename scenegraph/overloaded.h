// A set of lambdas as one visitor for std::visit: Overloaded{[](const A&) {...}, ...}. A
// variant alternative without its lambda does not compile, which keeps every dispatch over
// a variant (texture kinds, shapes) complete.
#pragma once

namespace lucent {

template <class... Fs>
struct Overloaded : Fs... {
  using Fs::operator()...;
};
template <class... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;

}  // namespace lucent
