// A name -> factory table for one kind of pluggable part (profiles, criteria, controllers).
#pragma once

#include <algorithm>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "engine/base/parameters.hpp"

namespace mdrsim {

template <class Part, class... Context>
class PartRegistry {
 public:
  using Factory = std::function<std::unique_ptr<Part>(const ParameterValues&, Context...)>;

  struct Entry {
    std::string name;
    std::string summary;  ///< one line for listings
    std::vector<ParameterSpec> parameters;
    Factory create;
  };

  /// Adds a part; a name can be registered once.
  void add(Entry entry) {
    if (entry.name.empty() || !entry.create) {
      throw std::invalid_argument("a registered part needs a name and a factory");
    }
    if (find(entry.name) != nullptr) {
      throw std::invalid_argument("part '" + entry.name + "' is registered already");
    }
    entries_.push_back(std::move(entry));
  }

  const Entry* find(std::string_view name) const {
    const auto it = std::find_if(entries_.begin(), entries_.end(),
                                 [&](const Entry& e) { return e.name == name; });
    return it == entries_.end() ? nullptr : &*it;
  }

  /// Registered names in alphabetical order.
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    out.reserve(entries_.size());
    for (const auto& e : entries_) out.push_back(e.name);
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  std::vector<Entry> entries_;
};

}  // namespace mdrsim
