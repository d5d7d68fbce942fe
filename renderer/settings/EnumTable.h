#pragma once
// One table per enum that the command line, scripts, scene files, the UI and the GLSL share: each
// value's name (what users type; never change one), its UI label and description, and the name of
// the GLSL constant that holds it. The shaders get their constants generated from these tables
// (GlslEnums.h), so the C++ and GLSL numbering cannot drift apart.

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ptview {

template <typename E>
struct EnumEntry {
    E value;
    const char* name;             // command line, scripts, scene files
    const char* label = nullptr;  // UI combos; nullptr: the name
    const char* description = ""; // UI tooltip and --help
    const char* glslConstant = nullptr; // nullptr: not a GLSL constant

    const char* displayLabel() const { return label ? label : name; }
};

template <typename E>
class EnumTable {
public:
    EnumTable(std::initializer_list<EnumEntry<E>> entries) : entries_(entries) {}

    auto begin() const { return entries_.begin(); }
    auto end() const { return entries_.end(); }
    std::size_t size() const { return entries_.size(); }
    const EnumEntry<E>& front() const { return entries_.front(); }

    // The entry of `value`; the first one for a value outside the table (a bad cast).
    const EnumEntry<E>& entry(E value) const {
        for (const EnumEntry<E>& e : entries_)
            if (e.value == value) return e;
        return entries_.front();
    }
    // "?" for a value outside the table.
    const char* name(E value) const {
        for (const EnumEntry<E>& e : entries_)
            if (e.value == value) return e.name;
        return "?";
    }
    std::optional<E> parse(const std::string& name) const {
        for (const EnumEntry<E>& e : entries_)
            if (name == e.name) return e.value;
        return std::nullopt;
    }
    std::vector<std::string> names() const {
        std::vector<std::string> result;
        for (const EnumEntry<E>& e : entries_) result.emplace_back(e.name);
        return result;
    }
    // "repeat, clamp, mirror": the names, for a message listing what was expected.
    std::string nameList() const {
        std::string list;
        for (const EnumEntry<E>& e : entries_) list += (list.empty() ? "" : ", ") + std::string(e.name);
        return list;
    }
    // For CLI11's CheckedTransformer.
    std::vector<std::pair<std::string, E>> namesAndValues() const {
        std::vector<std::pair<std::string, E>> result;
        for (const EnumEntry<E>& e : entries_) result.emplace_back(e.name, e.value);
        return result;
    }
    // "const uint kName = 3u; // name\n" for each entry with a GLSL constant.
    std::string glslConstants() const {
        std::string text;
        for (const EnumEntry<E>& e : entries_)
            if (e.glslConstant)
                text += std::string("const uint ") + e.glslConstant + " = " +
                        std::to_string(static_cast<std::uint32_t>(e.value)) + "u; // " + e.name + "\n";
        return text;
    }

private:
    std::vector<EnumEntry<E>> entries_;
};

} // namespace ptview
