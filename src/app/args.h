// Reading a flag's value (command_line.h's tables call these): every bad flag or value is one
// clear dsr::Error naming the flag, what was expected and what was given.
#pragma once
#include <string>
#include <vector>

namespace dsr {

class Args {
public:
    Args(std::string command, std::vector<std::string> args) : cmd_(std::move(command)), a_(std::move(args)) {}
    bool done() const { return i_ >= a_.size(); }
    const std::string& peek() const { return a_[i_]; }
    // An empty argument is never meant: a shell variable that was not set (never "the default").
    std::string next() {
        if (a_[i_].empty()) fail("expected an argument, got ''");
        return a_[i_++];
    }
    // The value after flag `flag`; throws if missing.
    std::string value(const std::string& flag);
    int int_value(const std::string& flag, int lo, int hi);
    float float_value(const std::string& flag, float lo, float hi);
    void size_value(const std::string& flag, int& w, int& h);  // WxH
    bool on_off(const std::string& flag);
    std::string choice(const std::string& flag, const std::vector<std::string>& allowed);
    [[noreturn]] void fail(const std::string& what) const;

private:
    std::string cmd_;
    std::vector<std::string> a_;
    size_t i_ = 0;
};

// "dsr COMMAND: what" as a dsr::Error: a command's own check after its flags are read.
[[noreturn]] void fail_command(const std::string& command, const std::string& what);

}  // namespace dsr
