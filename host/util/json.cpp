#include "util/json.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace tsis {

Json Json::array(std::vector<Json> items) {
    Json j;
    j.kind_ = Kind::Array;
    j.items_ = std::move(items);
    return j;
}

Json Json::object() {
    Json j;
    j.kind_ = Kind::Object;
    return j;
}

Json& Json::set(const std::string& key, Json value) {
    kind_ = Kind::Object;
    for (auto& [k, v] : members_)
        if (k == key) {
            v = std::move(value);
            return *this;
        }
    members_.emplace_back(key, std::move(value));
    return *this;
}

Json& Json::push(Json value) {
    kind_ = Kind::Array;
    items_.push_back(std::move(value));
    return *this;
}

static void writeString(std::string& out, const std::string& s) {
    out += '"';
    for (char c : s) {
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\t':
                out += "\\t";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", c);
                    out += buf;
                } else {
                    out += c;
                }
        }
    }
    out += '"';
}

void Json::write(std::string& out, int indent, int depth) const {
    auto newline = [&](int d) {
        if (indent <= 0) return;
        out += '\n';
        out.append(static_cast<size_t>(indent * d), ' ');
    };
    switch (kind_) {
        case Kind::Null:
            out += "null";
            break;
        case Kind::Bool:
            out += bool_ ? "true" : "false";
            break;
        case Kind::Number: {
            if (!std::isfinite(number_)) {
                out += "null";  // JSON has no inf/nan
                break;
            }
            // Shortest text that reads back as the same double.
            char buf[32];
            auto res = std::to_chars(buf, buf + sizeof buf, number_);
            out.append(buf, res.ptr);
            break;
        }
        case Kind::String:
            writeString(out, string_);
            break;
        case Kind::Array: {
            // Short arrays of scalars stay on one line: [r, g, b].
            bool flat = items_.size() <= 4;
            for (const Json& i : items_)
                if (i.kind_ == Kind::Array || i.kind_ == Kind::Object) flat = false;
            out += '[';
            for (size_t k = 0; k < items_.size(); ++k) {
                if (k) out += flat ? ", " : ",";
                if (!flat) newline(depth + 1);
                items_[k].write(out, flat ? 0 : indent, depth + 1);
            }
            if (!flat && !items_.empty()) newline(depth);
            out += ']';
            break;
        }
        case Kind::Object: {
            out += '{';
            for (size_t k = 0; k < members_.size(); ++k) {
                if (k) out += ',';
                newline(depth + 1);
                writeString(out, members_[k].first);
                out += indent > 0 ? ": " : ":";
                members_[k].second.write(out, indent, depth + 1);
            }
            if (!members_.empty()) newline(depth);
            out += '}';
            break;
        }
    }
}

std::string Json::dump(int indent) const {
    std::string out;
    write(out, indent, 0);
    return out;
}

}  // namespace tsis
