// A minimal JSON writer: enough for --json outputs and --stats files.
#pragma once

#include <initializer_list>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace tsis {

class Json {
  public:
    Json() : kind_(Kind::Null) {}
    Json(double v) : kind_(Kind::Number), number_(v) {}
    Json(int v) : Json(static_cast<double>(v)) {}
    Json(long v) : Json(static_cast<double>(v)) {}
    Json(long long v) : Json(static_cast<double>(v)) {}
    Json(unsigned v) : Json(static_cast<double>(v)) {}
    Json(unsigned long v) : Json(static_cast<double>(v)) {}
    Json(unsigned long long v) : Json(static_cast<double>(v)) {}
    Json(bool v) : kind_(Kind::Bool), bool_(v) {}
    Json(const char* s) : kind_(Kind::String), string_(s) {}
    Json(std::string s) : kind_(Kind::String), string_(std::move(s)) {}

    static Json array(std::vector<Json> items = {});
    static Json object();

    // Objects keep insertion order, so outputs read in the order written.
    Json& set(const std::string& key, Json value);
    Json& push(Json value);

    std::string dump(int indent = 2) const;
    bool isNumber() const { return kind_ == Kind::Number; }
    double number() const { return number_; }  // 0 unless isNumber()

  private:
    enum class Kind { Null, Number, Bool, String, Array, Object };
    void write(std::string& out, int indent, int depth) const;

    Kind kind_;
    double number_ = 0;
    bool bool_ = false;
    std::string string_;
    std::vector<Json> items_;
    std::vector<std::pair<std::string, Json>> members_;
};

}  // namespace tsis
