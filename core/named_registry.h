// One registry pattern for everything that registers itself from a static initialiser (algorithms,
// polygon families): a function-local static vector per type, so that a registration from another
// translation unit always finds it constructed, kept sorted by `name`.
#pragma once

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace pd {

template <class T>
class NamedRegistry {
 public:
  static const std::vector<T>& all() { return items(); }

  // The entry called `name`, or nullptr.
  static const T* find(const std::string& name) {
    const auto it = position_of(name);
    return it != items().end() && it->name == name ? &*it : nullptr;
  }

  // Adds `item`; a second entry of the same name is a programming error.
  static bool add(T item) {
    const auto it = position_of(item.name);
    if (it != items().end() && it->name == item.name) throw std::logic_error("registered twice: " + item.name);
    items().insert(it, std::move(item));
    return true;
  }

  // The names, comma-separated, for messages.
  static std::string names() {
    std::string list;
    for (const T& item : items()) list += (list.empty() ? "" : ", ") + item.name;
    return list;
  }

 private:
  static std::vector<T>& items() {
    static std::vector<T> registered;
    return registered;
  }
  static typename std::vector<T>::iterator position_of(const std::string& name) {
    return std::lower_bound(items().begin(), items().end(), name,
                            [](const T& item, const std::string& key) { return item.name < key; });
  }
};

}  // namespace pd

#define PD_CONCAT_INNER(a, b) a##b
#define PD_CONCAT(a, b) PD_CONCAT_INNER(a, b)
