// SPDX-License-Identifier: BSL-1.0
#pragma once
// FunctionRef<R(Args...)>: a non-owning, non-allocating reference to a callable (an object
// pointer and a trampoline), so that routines taking a user's function object are compiled once
// in src/ and called through one indirect call per evaluation. The referenced callable must
// outlive the FunctionRef (it is built by an inline front end around the call and dies with it).

#include <memory>
#include <type_traits>
#include <utility>

namespace locus::detail {

template <class Signature>
class FunctionRef;

template <class R, class... Args>
class FunctionRef<R(Args...)> {
 public:
  template <class F>
  requires(!std::is_same_v<std::remove_cvref_t<F>, FunctionRef> && std::is_invocable_v<F&, Args...>)
      FunctionRef(F&& f)
  noexcept  // NOLINT(google-explicit-constructor): a parameter adaptor
      : object_(const_cast<void*>(static_cast<const void*>(std::addressof(f)))),
        call_([](void* o, Args... args) -> R {
          return static_cast<R>(
              (*static_cast<std::remove_reference_t<F>*>(o))(std::forward<Args>(args)...));
        }) {}

  R operator()(Args... args) const { return call_(object_, std::forward<Args>(args)...); }

 private:
  void* object_;
  R (*call_)(void*, Args...);
};

}  // namespace locus::detail
