// The parameter registry: a step declares each tunable value once, bound to one of its members,
// and gets from that one declaration the ImGui widget, `--set name=value`, `--list-params`,
// preset save/load and reset-to-defaults. Values are always validated: unknown names, text that
// is not a value, non-finite numbers and values outside the declared range are refused with a
// message that names the parameter and its range.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ocean {

enum class ParamType { Float, Int, Bool, Choice, Color, Text };

// A parameter's value in the slot its type uses: `number` for Float, Int, Bool (0/1) and Choice
// (the index), `color`, or `text`. What text parses to, the default, and what the split view saves
// and puts back.
struct ParamValue {
    double number = 0;
    glm::vec3 color{0.0f};
    std::string text;
};

// A change counter, the one way a step notices that parameters changed: a parameter declared with
// `.bumps(counter)` increments it whenever its value changes through the registry (--set, a
// preset, reset, the panel). A step compares the counter with the one it last built for, instead
// of comparing structs field by field; what no parameter bumps (the camera) rebuilds nothing.
struct Generation {
    unsigned value = 1;  // a step's "built for" starts at 0: the first frame always builds
};

class Param {
public:
    const std::string& name() const { return name_; }
    const std::string& help() const { return help_; }
    const std::string& group() const { return group_; }
    ParamType type() const { return type_; }

    // Chainable refinements of a declaration.
    // A declaration's own group takes it out of the open GroupScope altogether: its panel group
    // and its change counter (chain .bumps() to keep one). A parameter that only changed panels
    // but still bumped the scope's counter once dropped step07's bodies whenever the boat steered.
    Param& in_group(std::string group);
    Param& visible_if(std::function<bool()> predicate) { visible_ = std::move(predicate); return *this; }
    Param& logarithmic() { logarithmic_ = true; return *this; }
    Param& bumps(Generation& generation) { generations_.push_back(&generation); return *this; }

    bool visible() const { return !visible_ || visible_(); }
    bool is_logarithmic() const { return logarithmic_; }

    // Text form, as written by presets and read by --set.
    std::string value_text() const;
    std::string default_text() const;
    std::string range_text() const;  // "[0, 10]", "true|false", "orbit|fly", "r,g,b in [0, 1]"

    // Parses and validates `text`; on success stores it, on failure returns the message.
    std::optional<std::string> set_from_text(const std::string& text);
    // Parses and validates without storing (presets check every line before applying any).
    std::optional<std::string> check_text(const std::string& text) const;
    void reset() { store(default_); }
    // The value as it is, and storing one (already valid: from value() or parsed); storing bumps
    // the generations when the value changed.
    ParamValue value() const;
    void store(const ParamValue& value);

    // The bound value, for the UI: numbers (Float, Int, Bool as 0/1, Choice as its index) read and
    // written through one accessor whatever the storage (float, double, int, uint64, enum).
    double number() const { return get_(); }
    void set_number(double value);  // clamped to the range; bumps the generations when it changed
    glm::vec3* color_value() const { return color_; }
    std::string* text_value() const { return text_; }
    void bump_generations() const;  // a change made behind the registry's back (a colour widget)
    bool is_double_precision() const { return double_precision_; }
    // Whether `number` lies in the range, compared in the type the range was declared in: a float
    // parameter's ends as floats (0.2f is 0.200000003 as a double, which would refuse "0.2").
    bool in_range(double number) const;
    double min() const { return min_; }
    double max() const { return max_; }
    const std::vector<std::string>& choices() const { return choices_; }

private:
    friend class ParamRegistry;
    std::optional<std::string> parse(const std::string& text, ParamValue& out) const;
    std::string format(const ParamValue& value) const;  // the text form of a value of this type

    std::string name_, help_, group_;
    ParamType type_ = ParamType::Float;
    std::function<double()> get_;         // Float, Int, Bool, Choice
    std::function<void(double)> put_;
    glm::vec3* color_ = nullptr;
    std::string* text_ = nullptr;
    ParamValue default_;
    double min_ = 0, max_ = 0;
    std::vector<std::string> choices_;
    std::function<bool()> visible_;
    bool logarithmic_ = false;
    bool double_precision_ = false;  // add_double: formatted to every digit of the double
    std::vector<Generation*> generations_;
    Generation* scope_changes_ = nullptr;  // the counter the open GroupScope added, if any
};

class ParamRegistry {
public:
    // Each declaration binds a parameter to the variable the math uses; the variable's value when
    // it is declared is the default (the struct's own initialiser: the default is written once).
    // Names are snake_case, unique.
    Param& add_float(const std::string& name, float* value, float min, float max, const std::string& help);
    Param& add_float(const std::string& name, double* value, double min, double max, const std::string& help);
    // A number kept to double precision, written and read back to all its digits (a coordinate far
    // from the origin: float's steps 1000 km out are 6 cm). add_float's doubles are rounded to
    // float, so that what the panel and presets show is what is used.
    Param& add_double(const std::string& name, double* value, double min, double max, const std::string& help);
    Param& add_int(const std::string& name, int* value, int min, int max, const std::string& help);
    Param& add_int(const std::string& name, std::uint64_t* value, int min, int max, const std::string& help);
    Param& add_bool(const std::string& name, bool* value, const std::string& help);
    Param& add_choice(const std::string& name, int* value, std::vector<std::string> choices, const std::string& help);
    // An enum bound directly: choice i is the enumerator with value i.
    template <class Enum>
    Param& add_choice(const std::string& name, Enum* value, std::vector<std::string> choices, const std::string& help) {
        return add_number(name, ParamType::Choice, [value] { return double(int(*value)); },
                          [value](double v) { *value = Enum(int(v)); }, 0, double(choices.size()) - 1, help,
                          std::move(choices));
    }
    // An int that takes one of a few values (a resolution: 64, 128, ...), shown by value.
    Param& add_value_choice(const std::string& name, int* value, const std::vector<int>& values, const std::string& help);
    Param& add_color(const std::string& name, glm::vec3* value, const std::string& help);
    // Free text on one line (a file name): at most 1024 characters, no '#' (presets' comments).
    Param& add_text(const std::string& name, std::string* value, const std::string& help);

    // A block of declarations that share a panel group (and a change counter) says so once: while
    // the returned scope lives, every parameter declared goes into `group` and bumps `changes`
    // (a declaration's own .in_group() takes it out of the scope: group and counter). Scopes nest;
    // the outer one returns when the inner one ends.
    class GroupScope {
    public:
        GroupScope(ParamRegistry& registry, std::string group, Generation* changes)
            : registry_(registry), outer_group_(std::exchange(registry.group_, std::move(group))),
              outer_changes_(std::exchange(registry.changes_, changes)) {}
        ~GroupScope() {
            registry_.group_ = std::move(outer_group_);
            registry_.changes_ = outer_changes_;
        }
        GroupScope(const GroupScope&) = delete;
        GroupScope& operator=(const GroupScope&) = delete;

    private:
        ParamRegistry& registry_;
        std::string outer_group_;
        Generation* outer_changes_;
    };
    [[nodiscard]] GroupScope group(std::string name, Generation* changes = nullptr) {
        return GroupScope(*this, std::move(name), changes);
    }

    Param* find(const std::string& name);
    const std::vector<std::unique_ptr<Param>>& all() const { return params_; }
    // Takes back parameters declared by an earlier chapter's declaration that a later chapter
    // does not show (their variables keep their defaults). A name that is not declared is a
    // programming error (std::logic_error), so a renamed parameter cannot slip through.
    void remove(const std::vector<std::string>& names);
    // Starts a parameter a part declared at the program's own default (a sea declared by its part,
    // a calmer wind in this program): the value now, and the default that --list-params, the
    // panel's tooltip and reset_all show. `value` is checked as --set checks it (a number: as its
    // text). A name not declared or a value --set refuses is a programming error (std::logic_error).
    void set_default(const std::string& name, const std::string& value);
    void set_default(const std::string& name, double number);

    // "name=value" as given to --set. Returns an error message or nothing.
    std::optional<std::string> set_assignment(const std::string& assignment);
    std::optional<std::string> set(const std::string& name, const std::string& value);
    void reset_all();

    // Presets: `name = value` lines, '#' comments, blank lines ignored (see README).
    // Loading checks every line first and applies nothing if any line is bad.
    std::optional<std::string> load_preset(const std::string& path);
    std::optional<std::string> save_preset(const std::string& path, const std::string& header) const;
    std::optional<std::string> apply_preset_text(const std::string& text, const std::string& origin);
    std::string preset_text(const std::string& header) const;

    std::string list_text() const;  // the table --list-params prints

private:
    Param& add(std::unique_ptr<Param> param);
    template <class T>  // float, double, int, uint64 storage
    Param& bind(const std::string& name, ParamType type, T* value, double min, double max, const std::string& help);
    // A number bound through accessors; the default is the value they read now.
    Param& add_number(const std::string& name, ParamType type, std::function<double()> get,
                      std::function<void(double)> put, double min, double max, const std::string& help,
                      std::vector<std::string> choices = {});
    std::string unknown_name_message(const std::string& name) const;

    std::vector<std::unique_ptr<Param>> params_;
    std::string group_;              // of the GroupScope that is open, if any
    Generation* changes_ = nullptr;  // likewise
};

}  // namespace ocean
