// Per-stage GPU times from GL timer queries, accumulated over frames. Each stage is a pair
// of GL_TIMESTAMP queries (glQueryCounter), so stages may nest: "total" brackets a whole
// frame around "view_generation" and "eia" (GL_TIME_ELAPSED queries cannot nest).
// Queries are read back lazily, in order, so timing does not stall the GPU more than
// necessary; finish() collects everything outstanding.
#pragma once

#include "gl_handles.h"

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace lfd::player {

struct StageTimes {
    std::vector<double> ms; // one entry per frame
    double mean() const;
    double median() const;
    double min() const;
    double max() const;
};

class GpuTimer {
public:
    GpuTimer();
    ~GpuTimer();

    void begin(std::string_view stage); // stages may nest; end() closes the innermost
    void end();
    void finish(); // waits for and collects all pending results
    const std::map<std::string, StageTimes>& stages() const { return stages_; }

private:
    struct Pending;
    std::vector<std::unique_ptr<Pending>> pending_; // submission order
    std::vector<gl::Query> freeQueries_;             // read back, ready for reuse
    std::vector<Pending*> open_;                     // begun, not yet ended (innermost last)
    gl::Query takeQuery();
    void collect(bool wait);
    std::map<std::string, StageTimes> stages_;
};

} // namespace lfd::player
