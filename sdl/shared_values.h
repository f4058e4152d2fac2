// Values whose copies share one T until one of them is changed (copy on write). A
// PovObject is copied each time a declared object is used (`object { X }`, a union of it),
// and its textures are most of its size and its children most of a union's: held here, a
// copy of a union of thousands of textured objects copies two pointers, not megabytes.
#pragma once

#include <memory>
#include <optional>
#include <utility>

namespace lucent::sdl {

template <class T>
class SharedOptional {
 public:
  SharedOptional() = default;
  SharedOptional(std::nullopt_t) {}
  SharedOptional(T value) : value_(std::make_shared<T>(std::move(value))) {}

  SharedOptional& operator=(std::nullopt_t) {
    value_.reset();
    return *this;
  }
  SharedOptional& operator=(T value) {
    value_ = std::make_shared<T>(std::move(value));
    return *this;
  }

  bool has_value() const { return value_ != nullptr; }
  explicit operator bool() const { return has_value(); }
  void reset() { value_.reset(); }

  // Reading shares; `edit` gives the value to change, copied first if another holds it.
  const T& operator*() const { return *value_; }
  const T* operator->() const { return value_.get(); }
  T& edit() {
    if (value_.use_count() > 1) value_ = std::make_shared<T>(*value_);
    return *value_;
  }

 private:
  std::shared_ptr<T> value_;
};

// A T that is always there (a default T until set), shared the same way.
template <class T>
class SharedValue {
 public:
  const T& operator*() const { return value_ ? *value_ : empty(); }
  const T* operator->() const { return &**this; }
  T& edit() {
    if (!value_) value_ = std::make_shared<T>();
    else if (value_.use_count() > 1) value_ = std::make_shared<T>(*value_);
    return *value_;
  }

 private:
  static const T& empty() {
    static const T none{};
    return none;
  }
  std::shared_ptr<T> value_;
};

}  // namespace lucent::sdl
