// Errors from inside the renderer ("frustum_planes: degenerate far plane ...") say nothing of
// what the command was doing or with which file; every user mistake is caught, with its file and
// line, before them (scene/user_file.h, the scene parser), so one reaching the user is a bug or a
// limit of the GL, and the report must say where. A Stage marks a stretch of a command; when an
// exception leaves it, main() prefixes the message with the stage: "dsr render: rendering
// a.scene: frustum_planes: ...".
#pragma once
#include <exception>
#include <string>

namespace dsr {

class Stage {
public:
    explicit Stage(std::string what) : what_(std::move(what)), unwinding_(std::uncaught_exceptions()) {}
    ~Stage();
    Stage(const Stage&) = delete;
    Stage& operator=(const Stage&) = delete;

private:
    std::string what_;
    int unwinding_;
};

// The innermost stage the escaping exception left ("" for none), read once by main().
std::string take_failed_stage();

}  // namespace dsr
