// Standard output under --json: the JSON document is all that goes there. While a JsonStdout is on,
// everything else a command prints (its human lines, a child program's output) goes to standard error.
#pragma once

namespace ricochet::app {

/// Turned on, points standard output (stdio and file descriptor 1, so children inherit it) at standard
/// error until restore() or the end of its scope; off, does nothing.
class JsonStdout {
public:
    explicit JsonStdout(bool on);
    ~JsonStdout();
    JsonStdout(const JsonStdout&) = delete;
    JsonStdout& operator=(const JsonStdout&) = delete;

    /// True if --json was asked for.
    bool on() const { return on_; }
    /// Gives standard output back (flushing what went to standard error first); the document is written
    /// after it. Idempotent.
    void restore();

private:
    bool on_ = false;
    int saved_ = -1;
};

}  // namespace ricochet::app
