#include <ptview/scene/SceneJson.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <vector>

namespace ptview::sceneFile {
namespace {

// nlohmann's messages carry an exception id and its own line/column (which counts a newline as
// column 0 of the next line); keep only the reason, without the echo of the last token, which
// for an unterminated string can be the rest of the file.
std::string shortSyntaxReason(std::string message) {
    auto dropThrough = [&message](const std::string& marker) {
        if (std::size_t at = message.find(marker); at != std::string::npos)
            message.erase(0, at + marker.size());
    };
    dropThrough("] ");
    if (message.rfind("parse error", 0) == 0)
        dropThrough(": ");
    if (message.rfind("syntax error while parsing", 0) == 0)
        dropThrough(" - ");
    const std::string lastRead = "; last read: '";
    if (std::size_t begin = message.find(lastRead); begin != std::string::npos) {
        std::size_t expected = message.find("'; expected ", begin + lastRead.size());
        std::size_t end = expected == std::string::npos ? message.size() : expected + 1;
        message.erase(begin, end - begin);
    }
    return message;
}

// How deeply arrays and objects may sit inside one another; a scene needs fewer than ten levels
// (the deepest: gltf / entry / materials / name / texture input / scale). Deeper documents are
// refused while they are read, before any recursive code sees them: ordered_json keeps an
// object's members in a vector of pair<const key, value>, which grows by copying its members (the
// pair's move copies the const key, may throw, so the vector does not use it), and that copy
// recurses once per level, as dump() and operator== do. A file of 100000 nested arrays followed
// by another key overflowed the stack.
constexpr std::size_t kMaxNesting = 64;

// 1-based line and column (in UTF-8 characters, as editors count) of a byte offset.
std::pair<int, int> lineAndColumn(const std::string& text, std::size_t offset) {
    offset = std::min(offset, text.size());
    int line = 1;
    std::size_t lineStart = 0;
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++line;
            lineStart = i + 1;
        }
    }
    int column = 1;
    for (std::size_t i = lineStart; i < offset; ++i) {
        bool isContinuationByte = (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80;
        column += isContinuationByte ? 0 : 1;
    }
    return {line, column};
}

// Where a value still open at the end of text began (an object, an array or a string), with its
// kind; nullopt when none is open. A file cut short (an editor saving, a hot reload halfway
// through) only fails at its end, which says nothing about what is unclosed. When a brace is
// missing mid-file, the next closer closes the wrong value and the one left open is an outer
// one, often the whole document; in a file laid out by lines the mistake shows as a closer on a
// line of its own indented less than the line its (count-matched) opener is on, so that opener
// is named instead, as a guess.
struct UnclosedValue {
    const char* kind;
    std::size_t offset;
    std::optional<std::size_t> misplacedCloser; // set for the guess: the closer that gave it away
};

std::optional<UnclosedValue> unclosedValue(const std::string& text) {
    struct Open {
        UnclosedValue value;
        std::size_t lineIndent;
    };
    std::vector<Open> open;
    std::optional<UnclosedValue> guess;
    std::optional<std::size_t> stringStart;
    std::size_t indent = 0;
    bool onlySpaceSoFar = true; // on this line, before the current character
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (stringStart) {
            if (c == '\\') ++i; // the escaped character cannot end the string
            else if (c == '"') stringStart.reset();
            continue;
        }
        if (c == '\n') {
            indent = 0, onlySpaceSoFar = true;
            continue;
        }
        if (onlySpaceSoFar && (c == ' ' || c == '\t')) {
            ++indent;
            continue;
        }
        bool firstOnLine = onlySpaceSoFar;
        onlySpaceSoFar = false;
        if (c == '"') stringStart = i;
        else if (c == '{') open.push_back({{"object", i, std::nullopt}, indent});
        else if (c == '[') open.push_back({{"array", i, std::nullopt}, indent});
        else if ((c == '}' || c == ']') && !open.empty()) {
            if (firstOnLine && indent < open.back().lineIndent && !guess)
                guess = UnclosedValue{open.back().value.kind, open.back().value.offset, i};
            open.pop_back();
        }
    }
    if (stringStart) return UnclosedValue{"string", *stringStart, std::nullopt};
    if (open.empty()) return std::nullopt;
    return guess ? guess : open.back().value;
}

} // namespace

// Builds the document through nlohmann's SAX interface instead of Json::parse for three things
// Json::parse cannot do: reject duplicate keys (it keeps the last one silently, so a copied
// material that was not renamed would replace the original), name the value whose number
// overflows, such as 1e999 (it reports that without any position), and bound the nesting
// (kMaxNesting).
class DocumentBuilder final : public nlohmann::json_sax<Json> {
public:
    Json root;

    DocumentBuilder() = default;
    DocumentBuilder(const DocumentBuilder&) = delete;
    DocumentBuilder& operator=(const DocumentBuilder&) = delete;
    ~DocumentBuilder() override { dismantle(); }

    bool null() override { return addValue(nullptr); }
    bool boolean(bool value) override { return addValue(value); }
    bool number_integer(number_integer_t value) override { return addValue(value); }
    bool number_unsigned(number_unsigned_t value) override { return addValue(value); }
    bool number_float(number_float_t value, const string_t&) override { return addValue(value); }
    bool string(string_t& value) override { return addValue(std::move(value)); }
    bool binary(binary_t& value) override { return addValue(Json::binary(std::move(value))); }

    bool start_object(std::size_t) override { return openContainer(Json::object()); }
    bool end_object() override { return closeContainer(); }
    bool start_array(std::size_t) override { return openContainer(Json::array()); }
    bool end_array() override { return closeContainer(); }

    bool key(string_t& name) override {
        Frame& top = stack.back();
        if (top.container->contains(name))
            fail(placeWithin(stack.size() - 1) / name, "duplicate key");
        top.key = std::move(name);
        return true;
    }

    bool parse_error(std::size_t position, const std::string& lastToken,
                     const Json::exception& error) override {
        constexpr int kNumberOverflow = 406;
        if (error.id == kNumberOverflow)
            fail(placeWithin(stack.size()), "number " + lastToken + " is out of range");
        // position counts bytes read, so it is one past the offending byte.
        throw SyntaxError(position > 0 ? position - 1 : 0, shortSyntaxReason(error.what()));
    }

private:
    struct Frame {
        Json* container;
        std::string key; // objects: the key whose value is being read
    };
    // Pointers stay valid: only the innermost container grows, and none of its elements is open.
    std::vector<Frame> stack;

    // Frees the document innermost value first, so that no container still holds another when
    // it is destroyed. nlohmann's destructor moves nested containers onto a vector it allocates;
    // when the memory ran out while the document was built, that allocation fails inside a
    // destructor during the unwinding, which is std::terminate. The path down reuses `stack`,
    // whose capacity is the document's depth, so nothing here allocates.
    void dismantle() noexcept {
        stack.clear();
        if (root.is_structured()) stack.push_back({&root, {}});
        while (!stack.empty()) {
            Json& container = *stack.back().container;
            if (container.empty()) {
                stack.pop_back();
                continue;
            }
            Json& last = container.is_array() ? container.back() : container.get_ref<Json::object_t&>().back().second;
            if (last.is_structured() && !last.empty() && stack.size() < stack.capacity()) {
                stack.push_back({&last, {}});
                continue;
            }
            if (container.is_array()) container.get_ref<Json::array_t&>().pop_back();
            else container.get_ref<Json::object_t&>().pop_back();
        }
    }

    Json* place(Json&& value) {
        if (stack.empty()) {
            root = std::move(value);
            return &root;
        }
        Frame& top = stack.back();
        if (top.container->is_array()) {
            top.container->push_back(std::move(value));
            return &top.container->back();
        }
        Json& slot = (*top.container)[top.key];
        slot = std::move(value);
        return &slot;
    }
    bool addValue(Json&& value) {
        place(std::move(value));
        return true;
    }
    bool openContainer(Json&& empty) {
        // Named by the top-level member that holds it: the full pointer would be kMaxNesting
        // levels long, each a key of any length.
        if (stack.size() >= kMaxNesting)
            fail(placeWithin(1), "arrays and objects nested deeper than " + std::to_string(kMaxNesting) + " levels");
        stack.push_back({place(std::move(empty)), {}});
        return true;
    }
    bool closeContainer() {
        stack.pop_back();
        return true;
    }

    // The pointer through the outermost `depth` open containers. In an enclosing array the open
    // element is the last one; in the innermost container the value being read is not added yet.
    Pointer placeWithin(std::size_t depth) const {
        Pointer at;
        for (std::size_t i = 0; i < depth; ++i) {
            const Frame& frame = stack[i];
            if (frame.container->is_object()) {
                at /= frame.key;
            } else {
                bool isOpenElement = i + 1 < stack.size();
                at /= frame.container->size() - (isOpenElement ? 1 : 0);
            }
        }
        return at;
    }
};

// Keys and strings may hold escaped newlines ("a\nb"), which must not break the message in two.
SceneError oneLineError(const std::string& message) {
    std::string line;
    for (char c : message) {
        auto code = static_cast<unsigned char>(c);
        if (code < 0x20 || code == 0x7F) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04X", code);
            line += escaped;
        } else {
            line += c;
        }
    }
    return SceneError(line);
}

std::string describe(const Json& value) {
    switch (value.type()) {
    case Json::value_t::object: return "an object";
    case Json::value_t::array: return "an array";
    case Json::value_t::string: return "a string";
    case Json::value_t::boolean: return "a boolean";
    case Json::value_t::null: return "null";
    default: return "a number";
    }
}

Document::Document(const std::string& text) : builder_(std::make_unique<DocumentBuilder>()) {
    Json::sax_parse(text, builder_.get(), Json::input_format_t::json, /*strict=*/true);
}

Document::~Document() = default;

const Json& Document::root() const { return builder_->root; }

SceneError sceneError(const PlaceError& error, const std::string& file) {
    std::string where = error.where.to_string();
    // The whole document has the empty pointer, which would read as a stray ": ".
    return oneLineError(file + ": " + (where.empty() ? "" : where + ": ") + error.what());
}

SceneError sceneError(const SyntaxError& error, const std::string& jsonText, const std::string& file) {
    auto place = [&](std::size_t offset) {
        auto [line, column] = lineAndColumn(jsonText, offset);
        return file + ":" + std::to_string(line) + ":" + std::to_string(column);
    };
    std::string message = place(error.offset) + ": malformed JSON: " + error.what();
    // The end says only that something is missing; where the unclosed value began says what.
    if (error.offset >= jsonText.size()) {
        if (std::optional<UnclosedValue> unclosed = unclosedValue(jsonText)) {
            message += "; " + place(unclosed->offset) + ": unclosed " + unclosed->kind + " begun here";
            if (unclosed->misplacedCloser) {
                auto [line, column] = lineAndColumn(jsonText, *unclosed->misplacedCloser);
                message += " (probably: the '" + std::string(1, jsonText[*unclosed->misplacedCloser]) + "' at " +
                           std::to_string(line) + ":" + std::to_string(column) +
                           " closes it by count but is indented as an outer one's)";
            }
        }
    }
    return oneLineError(message);
}

} // namespace ptview::sceneFile
