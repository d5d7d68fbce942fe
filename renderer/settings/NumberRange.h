#pragma once
// A closed, open or half-open range of numbers with what the number is, for the tables of ranges
// that loaders, writers, the command line, scripts and panels all read (SceneRanges.h for the
// scene model, SettingRanges.h for the render settings): one bound, many readers.

#include <cmath>
#include <cstdio>
#include <string>

namespace ptview {

struct NumberRange {
    const char* quantity;    // for messages and docs: "spot cone angle"
    double lo, hi;           // an infinite bound: unbounded on that side (any finite float)
    bool loOpen, hiOpen;     // an open end excludes the bound itself
    const char* unit;        // "deg", "W sr^-1", ""
    const char* description; // what the quantity is, for tooltips and docs
    // What the panels' sliders and drags span: inside the range (a slider cannot stop short of an
    // open end) and, for an unbounded side, what a drag reasonably reaches. The panels clamp a
    // typed value (Ctrl+click) to it, except the environment rotation, which wraps into one turn.
    float panelLo, panelHi;
    bool integer = false;    // only whole numbers (a count, a size, a seed)

    bool contains(double value) const {
        if (std::isnan(value)) return false;
        if (integer && value != std::floor(value)) return false;
        bool aboveLo = loOpen ? value > lo : value >= lo;
        bool belowHi = hiOpen ? value < hi : value <= hi;
        return aboveLo && belowHi;
    }
    // The value as a setting stores it: an integer as it is, any other number as the float it
    // rounds to, against bounds rounded the same way, so that a bound no float holds (1e-6)
    // stands for the float nearest it, which is what a user who types the bound gets.
    bool containsAsStored(double value) const {
        if (integer) return contains(value);
        NumberRange asStored = *this;
        asStored.lo = static_cast<float>(lo), asStored.hi = static_cast<float>(hi);
        return asStored.contains(static_cast<float>(value));
    }
    bool boundedBelow() const { return std::isfinite(lo); }
    bool boundedAbove() const { return std::isfinite(hi); }

    // "in (0, 90]", ">= 0", "> 0", "<= 1"; empty for any finite number.
    std::string text() const {
        if (boundedBelow() && boundedAbove())
            return std::string("in ") + (loOpen ? "(" : "[") + number(lo) + ", " + number(hi) + (hiOpen ? ")" : "]");
        if (boundedBelow()) return (loOpen ? "> " : ">= ") + number(lo);
        if (boundedAbove()) return (hiOpen ? "< " : "<= ") + number(hi);
        return "";
    }
    // As the loader says what it expected: "a number in (0, 90]", "a non-negative number".
    std::string expected() const {
        const std::string noun = integer ? "integer" : "number";
        if (boundedBelow() && !boundedAbove() && lo == 0.0) return (loOpen ? "a positive " : "a non-negative ") + noun;
        const std::string article = integer ? "an " : "a ";
        return text().empty() ? article + noun : article + noun + " " + text();
    }

private:
    static std::string number(double value) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.10g", value);
        return buffer;
    }
};

} // namespace ptview
