#include "common/params.hpp"

#include "common/text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <string_view>

namespace ocean {

namespace {

// Reads a whole finite number, or nothing ("1e3" yes, "1e3x", "", "nan", "inf" no).
std::optional<double> parse_number(const std::string& text, bool* non_finite) {
    const std::string t = trim(text);
    *non_finite = false;
    if (t.empty()) return std::nullopt;
    char* end = nullptr;
    const double value = std::strtod(t.c_str(), &end);
    if (end != t.c_str() + t.size()) return std::nullopt;
    if (!std::isfinite(value)) {
        *non_finite = true;
        return std::nullopt;
    }
    return value;
}

std::optional<bool> parse_bool(const std::string& text) {
    const std::string t = lowercase(trim(text));
    if (t == "true" || t == "1" || t == "on" || t == "yes") return true;
    if (t == "false" || t == "0" || t == "off" || t == "no") return false;
    return std::nullopt;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

std::string Param::range_text() const {
    switch (type_) {
        case ParamType::Float:
        case ParamType::Int: return "[" + format_number(min_) + ", " + format_number(max_) + "]";
        case ParamType::Bool: return "true|false";
        case ParamType::Choice: return join(choices_, "|");
        case ParamType::Color: return "r,g,b each in [0, 1]";
        case ParamType::Text: return "text";
    }
    return "";
}

std::string Param::format(const ParamValue& v) const {
    switch (type_) {
        case ParamType::Float: return double_precision_ ? format_double(v.number) : format_number(v.number);
        case ParamType::Int: return std::to_string(static_cast<long long>(v.number));
        case ParamType::Bool: return v.number != 0 ? "true" : "false";
        case ParamType::Choice: return choices_.at(static_cast<std::size_t>(v.number));
        case ParamType::Color:
            return format_number(v.color.r) + "," + format_number(v.color.g) + "," + format_number(v.color.b);
        case ParamType::Text: return v.text;
    }
    return "";
}

std::string Param::value_text() const { return format(value()); }
std::string Param::default_text() const { return format(default_); }

// The one place a value meets its storage: a number through the accessors, or the bound colour or
// text.
ParamValue Param::value() const {
    ParamValue v;
    if (get_) v.number = get_();
    if (color_ != nullptr) v.color = *color_;
    if (text_ != nullptr) v.text = *text_;
    return v;
}

void Param::store(const ParamValue& value) {
    const std::string before = value_text();
    if (put_) put_(value.number);
    if (color_ != nullptr) *color_ = value.color;
    if (text_ != nullptr) *text_ = value.text;
    if (value_text() != before) bump_generations();
}

std::optional<std::string> Param::parse(const std::string& text, ParamValue& out) const {
    const std::string shown = "'" + ellipsize(text, 40) + "'";
    bool non_finite = false;
    switch (type_) {
        case ParamType::Float:
        case ParamType::Int: {
            const auto number = parse_number(text, &non_finite);
            const bool whole = number && (type_ == ParamType::Float || *number == std::floor(*number));
            if (non_finite)
                return "parameter '" + name_ + "' must be a finite number in " + range_text() +
                       ", got " + shown;
            if (!number || !whole)
                return "parameter '" + name_ + "' expects " +
                       (type_ == ParamType::Int ? "an integer" : "a number") + " in " +
                       range_text() + ", got " + shown;
            if (!in_range(*number))
                return "parameter '" + name_ + "' = " + trim(text) + " is outside its range " +
                       range_text();
            out.number = *number;
            return std::nullopt;
        }
        case ParamType::Bool: {
            const auto value = parse_bool(text);
            if (!value)
                return "parameter '" + name_ + "' expects true or false, got " + shown;
            out.number = *value ? 1 : 0;
            return std::nullopt;
        }
        case ParamType::Choice: {
            const std::string t = lowercase(trim(text));
            for (std::size_t i = 0; i < choices_.size(); ++i)
                if (t == choices_[i]) {
                    out.number = static_cast<double>(i);
                    return std::nullopt;
                }
            return "parameter '" + name_ + "' expects one of " + range_text() + ", got " + shown;
        }
        case ParamType::Color: {
            const auto parts = split(text, ',');
            if (parts.size() != 3)
                return "parameter '" + name_ + "' expects a colour r,g,b with each in [0, 1], got " +
                       shown;
            for (int c = 0; c < 3; ++c) {
                const auto v = parse_number(parts[static_cast<std::size_t>(c)], &non_finite);
                if (!v || *v < 0 || *v > 1)
                    return "parameter '" + name_ + "' expects a colour r,g,b with each in [0, 1], got " +
                           shown;
                out.color[c] = static_cast<float>(*v);
            }
            return std::nullopt;
        }
        case ParamType::Text: {
            const std::string t = trim(text);
            if (t.size() > 1024) return "parameter '" + name_ + "' is longer than 1024 characters";
            if (t.find_first_of("#\n\r") != std::string::npos || t.find('\0') != std::string::npos)
                return "parameter '" + name_ + "' cannot hold '#' or line breaks, got " + shown;
            out.text = t;
            return std::nullopt;
        }
    }
    return "internal: unknown parameter type";
}

std::optional<std::string> Param::check_text(const std::string& text) const {
    ParamValue parsed;
    return parse(text, parsed);
}

std::optional<std::string> Param::set_from_text(const std::string& text) {
    ParamValue parsed;
    if (auto error = parse(text, parsed)) return error;
    store(parsed);
    return std::nullopt;
}

Param& Param::in_group(std::string group) {
    group_ = std::move(group);
    if (scope_changes_ != nullptr) {
        generations_.erase(std::find(generations_.begin(), generations_.end(), scope_changes_));
        scope_changes_ = nullptr;
    }
    return *this;
}

bool Param::in_range(double number) const {
    // add_float's ranges arrive as floats (or as doubles rounded to float when stored, see bind):
    // the text "0.95" and the declared 0.95f are the same float, not the same double.
    if (type_ == ParamType::Float && !double_precision_)
        return float(number) >= float(min_) && float(number) <= float(max_);
    return number >= min_ && number <= max_;
}

void Param::set_number(double value) {
    store({std::clamp(value, min_, max_), glm::vec3(0.0f), ""});
}

void Param::bump_generations() const {
    for (Generation* g : generations_) ++g->value;
}

Param& ParamRegistry::add(std::unique_ptr<Param> param) {
    if (find(param->name_) != nullptr)
        throw std::logic_error("parameter '" + param->name_ + "' declared twice");
    param->reset();  // the default stored (a double bound to a float range keeps its value)
    param->group_ = group_;
    if (changes_ != nullptr) param->generations_.push_back(param->scope_changes_ = changes_);
    params_.push_back(std::move(param));
    return *params_.back();
}

Param& ParamRegistry::add_number(const std::string& name, ParamType type, std::function<double()> get,
                                 std::function<void(double)> put, double min, double max, const std::string& help,
                                 std::vector<std::string> choices) {
    auto p = std::make_unique<Param>();
    p->name_ = name; p->help_ = help; p->type_ = type;
    p->default_.number = get();
    p->get_ = std::move(get); p->put_ = std::move(put);
    p->min_ = min; p->max_ = max; p->choices_ = std::move(choices);
    return add(std::move(p));
}

template <class T>
Param& ParamRegistry::bind(const std::string& name, ParamType type, T* value, double min, double max,
                           const std::string& help) {
    if constexpr (std::is_same_v<T, double>) {
        // Stored as a float would be (what the panel and presets show), so that a preset written
        // and read back gives the same double.
        *value = double(float(*value));
        return add_number(name, type, [value] { return *value; }, [value](double v) { *value = double(float(v)); },
                          min, max, help);
    } else {
        return add_number(name, type, [value] { return double(*value); }, [value](double v) { *value = T(v); }, min,
                          max, help);
    }
}

Param& ParamRegistry::add_float(const std::string& name, float* value, float min, float max, const std::string& help) {
    return bind(name, ParamType::Float, value, min, max, help);
}
Param& ParamRegistry::add_float(const std::string& name, double* value, double min, double max,
                                const std::string& help) {
    return bind(name, ParamType::Float, value, min, max, help);
}
Param& ParamRegistry::add_double(const std::string& name, double* value, double min, double max,
                                 const std::string& help) {
    Param& p = add_number(name, ParamType::Float, [value] { return *value; }, [value](double v) { *value = v; }, min,
                          max, help);
    p.double_precision_ = true;
    return p;
}
Param& ParamRegistry::add_int(const std::string& name, int* value, int min, int max, const std::string& help) {
    return bind(name, ParamType::Int, value, min, max, help);
}
Param& ParamRegistry::add_int(const std::string& name, std::uint64_t* value, int min, int max,
                              const std::string& help) {
    return bind(name, ParamType::Int, value, min, max, help);
}
Param& ParamRegistry::add_bool(const std::string& name, bool* value, const std::string& help) {
    return add_number(name, ParamType::Bool, [value] { return *value ? 1.0 : 0.0; },
                      [value](double v) { *value = v != 0; }, 0, 1, help);
}

Param& ParamRegistry::add_choice(const std::string& name, int* value, std::vector<std::string> choices,
                                 const std::string& help) {
    const double last = double(choices.size()) - 1;
    return add_number(name, ParamType::Choice, [value] { return double(*value); },
                      [value](double v) { *value = int(v); }, 0, last, help, std::move(choices));
}

Param& ParamRegistry::add_value_choice(const std::string& name, int* value, const std::vector<int>& values,
                                 const std::string& help) {
    std::vector<std::string> names;
    for (int v : values) names.push_back(std::to_string(v));
    const auto index_of = [values](int v) {
        const auto it = std::find(values.begin(), values.end(), v);
        return it == values.end() ? 0.0 : double(it - values.begin());
    };
    return add_number(name, ParamType::Choice, [value, index_of] { return index_of(*value); },
                      [value, values](double i) { *value = values.at(std::size_t(i)); }, 0,
                      double(values.size()) - 1, help, std::move(names));
}

Param& ParamRegistry::add_color(const std::string& name, glm::vec3* value, const std::string& help) {
    auto p = std::make_unique<Param>();
    p->name_ = name; p->help_ = help; p->type_ = ParamType::Color; p->color_ = value;
    p->default_.color = *value; p->min_ = 0; p->max_ = 1;
    return add(std::move(p));
}

Param& ParamRegistry::add_text(const std::string& name, std::string* value, const std::string& help) {
    auto p = std::make_unique<Param>();
    p->name_ = name; p->help_ = help; p->type_ = ParamType::Text; p->text_ = value;
    p->default_.text = *value;
    return add(std::move(p));
}

Param* ParamRegistry::find(const std::string& name) {
    for (auto& p : params_)
        if (p->name() == name) return p.get();
    return nullptr;
}

void ParamRegistry::remove(const std::vector<std::string>& names) {
    for (const auto& name : names) {
        const auto it = std::find_if(params_.begin(), params_.end(), [&](const auto& p) { return p->name() == name; });
        if (it == params_.end()) throw std::logic_error("parameter '" + name + "' removed but never declared");
        params_.erase(it);
    }
}

void ParamRegistry::set_default(const std::string& name, const std::string& value) {
    Param* p = find(name);
    if (p == nullptr) throw std::logic_error("parameter '" + name + "' given a default but never declared");
    ParamValue parsed = p->default_;
    if (auto error = p->parse(value, parsed)) throw std::logic_error(*error);
    p->default_ = parsed;
    p->reset();
    // What the variable holds, as a declaration takes it (a double bound to a float range: rounded).
    if (p->get_) p->default_.number = p->get_();
}

void ParamRegistry::set_default(const std::string& name, double number) { set_default(name, format_double(number)); }

std::string ParamRegistry::unknown_name_message(const std::string& name) const {
    std::string message = "unknown parameter '" + ellipsize(name, 40) + "'";
    const Param* closest = nullptr;
    std::size_t best = name.size() / 3 + 1;  // suggest only near misses: a typo, not another word
    for (const auto& p : params_) {
        const std::size_t d = edit_distance(name, p->name());
        if (d < best) { best = d; closest = p.get(); }
    }
    if (closest != nullptr) message += " (did you mean '" + closest->name() + "'?)";
    return message + "; --list-params lists them";
}

std::optional<std::string> ParamRegistry::set(const std::string& name, const std::string& value) {
    Param* p = find(name);
    if (p == nullptr) return unknown_name_message(name);
    return p->set_from_text(value);
}

std::optional<std::string> ParamRegistry::set_assignment(const std::string& assignment) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || trim(assignment.substr(0, eq)).empty())
        return "--set expects name=value, got '" + ellipsize(assignment, 40) + "'";
    return set(trim(assignment.substr(0, eq)), assignment.substr(eq + 1));
}

void ParamRegistry::reset_all() {
    for (auto& p : params_) p->reset();
}

std::string ParamRegistry::list_text() const {
    std::size_t name_width = 4, range_width = 5, value_width = 7;
    for (const auto& p : params_) {
        name_width = std::max(name_width, p->name().size());
        range_width = std::max(range_width, p->range_text().size());
        value_width = std::max(value_width, p->default_text().size());
    }
    std::ostringstream out;
    auto row = [&](const std::string& a, const std::string& b, const std::string& c,
                   const std::string& d) {
        out << pad_right(a, name_width) << "  " << pad_right(b, value_width) << "  "
            << pad_right(c, range_width) << "  " << d << "\n";
    };
    row("name", "default", "range", "meaning");
    for (const auto& p : params_) row(p->name(), p->default_text(), p->range_text(), p->help());
    return out.str();
}

}  // namespace ocean
