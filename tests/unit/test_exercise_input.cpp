// The exercise tool's input, read strictly (exercises/arguments.hpp, exercises/program_output.hpp):
// its command line, and what a learner's C++ check program prints.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "exercises/arguments.hpp"
#include "exercises/program_output.hpp"

namespace {

using exercises::CaseValues;
using exercises::Command;
using exercises::parse_command;
using exercises::parse_exercise_number;
using exercises::parse_program_output;
using exercises::Verb;

const std::vector<exercises::ExerciseId> kKnown{
    {"step01_sine2d", 1}, {"step01_sine2d", 2}, {"step05_fft", 8}, {"step07_buoyancy", 2}};

// The error for `args`, or "" when they parse.
std::string error_of(const std::vector<std::string>& args) {
    const auto parsed = parse_command(args, kKnown);
    const auto* error = std::get_if<std::string>(&parsed);
    return error == nullptr ? "" : *error;
}

TEST(ExerciseNumber, TakesOneToNineHundredNinetyNineInDigits) {
    EXPECT_EQ(parse_exercise_number("1"), 1);
    EXPECT_EQ(parse_exercise_number("10"), 10);
    EXPECT_EQ(parse_exercise_number("999"), 999);
}

TEST(ExerciseNumber, RefusesAnythingElse) {
    for (const char* text :
         {"", "0", "00", "02", "007", "-1", "+2", " 2", "2 ", "2abc", "1e1", "0x2", "2.0", "1000",
          "99999999999999999999", "2'; touch CANARY; '", "../../step01_sine2d", "\xd9\xa3", "\t3"})
        EXPECT_FALSE(parse_exercise_number(text).has_value()) << "'" << text << "'";
    EXPECT_FALSE(parse_exercise_number(std::string("2\0", 2)).has_value());
}

TEST(ExerciseCommand, ReadsEachVerb) {
    const auto check =
        std::get<Command>(parse_command({"check", "step07_buoyancy", "2", "work dir"}, kKnown));
    EXPECT_EQ(check.verb, Verb::Check);
    EXPECT_EQ(check.exercise.step, "step07_buoyancy");
    EXPECT_EQ(check.exercise.number, 2);
    EXPECT_EQ(check.work, "work dir");
    EXPECT_EQ(std::get<Command>(parse_command({"list"}, kKnown)).verb, Verb::List);
    EXPECT_EQ(std::get<Command>(parse_command({"hint", "step01_sine2d", "1"}, kKnown)).verb, Verb::Hint);
    EXPECT_EQ(std::get<Command>(parse_command({"flags", "step05_fft", "8"}, kKnown)).verb, Verb::Flags);
    EXPECT_EQ(std::get<Command>(parse_command({"prepare", "step01_sine2d", "2", "w"}, kKnown)).verb,
              Verb::Prepare);
}

TEST(ExerciseCommand, CountsTheArguments) {
    EXPECT_EQ(error_of({}).rfind("no verb: usage: ", 0), 0u);
    EXPECT_NE(error_of({"list", "step01_sine2d"}).find("list takes no arguments; given 1 argument"),
              std::string::npos);
    EXPECT_NE(
        error_of({"check", "step01_sine2d", "1"}).find("check takes STEP N WORK_DIR; given 2 arguments"),
        std::string::npos);
    EXPECT_NE(error_of({"hint", "step01_sine2d", "1", "extra"}).find("hint takes STEP N; given 3"),
              std::string::npos);
    EXPECT_NE(error_of({"run", "step01_sine2d", "1"}).find("unknown verb 'run'"), std::string::npos);
    EXPECT_NE(error_of({"CHECK", "step01_sine2d", "1", "w"}).find("unknown verb"), std::string::npos);
}

TEST(ExerciseCommand, ComparesTheStepAsText) {
    for (const char* step : {"step0.*", "step01_sine2d/../step02_sine3d", "step01_sine2d/", "STEP01_SINE2D",
                             "", "step02_sine3d"})
        EXPECT_EQ(error_of({"hint", step, "1"})
                      .rfind(std::string("no step '") + step +
                                 "' has exercises; these do: "
                                 "step01_sine2d, step05_fft, step07_buoyancy",
                             0),
                  0u)
            << step;
}

TEST(ExerciseCommand, NamesTheNumbersAStepHas) {
    EXPECT_EQ(error_of({"hint", "step01_sine2d", "8"}), "step01_sine2d has no exercise 8; it has 1, 2");
    EXPECT_NE(error_of({"hint", "step01_sine2d", "2abc"}).find("not '2abc' (step01_sine2d has 1, 2)"),
              std::string::npos);
}

TEST(ExerciseCommand, RefusesAnEmptyWorkFolder) {
    EXPECT_EQ(error_of({"prepare", "step01_sine2d", "1", ""}).rfind("WORK_DIR is empty", 0), 0u);
    EXPECT_EQ(error_of({"prepare", "step01_sine2d", "1", "w"}), "");
}

TEST(ExerciseCommand, EchoesWhatWasTypedOnOneShortLine) {
    const std::string error = error_of({"hint", "step01_sine2d\nstep02", std::string(100000, '9')});
    EXPECT_EQ(error.find('\n'), std::string::npos);
    EXPECT_LT(error.size(), 400u);
    EXPECT_LT(error_of({"hint", "step01_sine2d", std::string(100000, '9')}).size(), 400u);
}

// The numbers for `output`, failing the test with the parser's verdict when there are none.
CaseValues values_of(const std::string& output, std::size_t cases, std::size_t values) {
    const auto parsed = parse_program_output(output, cases, values);
    if (const auto* problem = std::get_if<std::string>(&parsed)) ADD_FAILURE() << *problem;
    return std::get_if<CaseValues>(&parsed) != nullptr ? std::get<CaseValues>(parsed) : CaseValues{};
}

std::string verdict_of(const std::string& output, std::size_t cases, std::size_t values) {
    const auto parsed = parse_program_output(output, cases, values);
    const auto* problem = std::get_if<std::string>(&parsed);
    return problem == nullptr ? "(it parsed)" : *problem;
}

TEST(ProgramOutput, ReadsOneLineOfNumbersACase) {
    EXPECT_EQ(values_of("1 2.5 -3e2\n0x1p3\t7 -0\n", 2, 3), (CaseValues{{1, 2.5, -300}, {8, 7, 0}}));
    EXPECT_EQ(values_of("1 2\n3 4", 2, 2), (CaseValues{{1, 2}, {3, 4}}));  // the last newline may be missing
    EXPECT_EQ(values_of("  4   5  \n", 1, 2), (CaseValues{{4, 5}}));
    EXPECT_EQ(values_of("1e-400\n", 1, 1), (CaseValues{{0}}));  // below double's range, but a number
    EXPECT_EQ(values_of("", 0, 3), CaseValues{});
}

TEST(ProgramOutput, NamesWhatIsNotAFiniteNumber) {
    EXPECT_EQ(verdict_of("1 2 3\n4 5 nan\n", 2, 3), "case 1, value 2 is not a number: nan");
    EXPECT_EQ(verdict_of("-nan 1\n", 1, 2), "case 0, value 0 is not a number: -nan");
    EXPECT_EQ(verdict_of("1 inf\n", 1, 2), "case 0, value 1 is infinite: inf");
    EXPECT_EQ(verdict_of("1e999 1\n", 1, 2), "case 0, value 0 is infinite: 1e999");
    EXPECT_EQ(verdict_of("1 abc 3\n", 1, 3), "case 0, value 1: 'abc' is not a number");
    EXPECT_EQ(verdict_of("2abc\n", 1, 1), "case 0, value 0: '2abc' is not a number");
    EXPECT_EQ(verdict_of("1,5\n", 1, 1), "case 0, value 0: '1,5' is not a number");
    EXPECT_EQ(verdict_of("\v1\n", 1, 1), "case 0, value 0: '?1' is not a number");
    EXPECT_EQ(verdict_of("1\r\n", 1, 1), "case 0, value 0: '1?' is not a number");
    EXPECT_EQ(verdict_of(std::string("1\0002\n", 4), 1, 1), "case 0, value 0: '1?2' is not a number");
}

TEST(ProgramOutput, CountsValuesAndLines) {
    EXPECT_EQ(verdict_of("1 2\n", 1, 3), "case 0 has 2 values, not 3");
    EXPECT_EQ(verdict_of("1 2 3 4\n", 1, 3), "case 0 has 4 values, not 3");
    EXPECT_EQ(verdict_of("1\n\n", 2, 1), "case 1 has 0 values, not 1");
    EXPECT_EQ(verdict_of("1\n2\n", 3, 1), "the program printed 2 lines, not 3 (one a case)");
    EXPECT_EQ(verdict_of("", 2, 1), "the program printed 0 lines, not 2 (one a case)");
    EXPECT_EQ(verdict_of("1\n2\n3\n", 2, 1), "the program printed a line after its 2 cases: '3'");
    EXPECT_EQ(verdict_of("1\n2\n\n", 2, 1), "the program printed a line after its 2 cases: ''");
}

TEST(ProgramOutput, KeepsEveryVerdictOnOneShortLine) {
    const std::string long_garbage(100000, 'x');
    for (const std::string& output :
         {long_garbage + "\n", "1\n" + long_garbage, "1 " + long_garbage + "\nmore"}) {
        const std::string verdict = verdict_of(output, 1, 2);
        EXPECT_EQ(verdict.find('\n'), std::string::npos);
        EXPECT_LT(verdict.size(), 300u);
    }
}

}  // namespace
