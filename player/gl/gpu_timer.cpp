#include "gpu_timer.h"

#include "gl_context.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <numeric>

namespace lfd::player {

double StageTimes::mean() const
{
    return ms.empty() ? 0.0 : std::accumulate(ms.begin(), ms.end(), 0.0) / double(ms.size());
}

double StageTimes::median() const
{
    if (ms.empty())
        return 0.0;
    std::vector<double> sorted = ms;
    std::sort(sorted.begin(), sorted.end());
    const size_t n = sorted.size();
    return n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
}

double StageTimes::min() const { return ms.empty() ? 0.0 : *std::min_element(ms.begin(), ms.end()); }
double StageTimes::max() const { return ms.empty() ? 0.0 : *std::max_element(ms.begin(), ms.end()); }

struct GpuTimer::Pending {
    std::string stage;
    gl::Query begin;
    gl::Query end; // empty while the stage is open
};

GpuTimer::GpuTimer() = default;
GpuTimer::~GpuTimer() = default; // Pending is complete here

gl::Query GpuTimer::takeQuery()
{
    if (freeQueries_.empty())
        return gl::createQuery(GL_TIMESTAMP);
    gl::Query q = std::move(freeQueries_.back());
    freeQueries_.pop_back();
    return q;
}

void GpuTimer::begin(std::string_view stage)
{
    collect(false);
    auto p = std::make_unique<Pending>(Pending{std::string(stage), takeQuery(), gl::Query()});
    glQueryCounter(p->begin, GL_TIMESTAMP);
    open_.push_back(p.get());
    pending_.push_back(std::move(p));
}

void GpuTimer::end()
{
    if (open_.empty())
        throw gl::GlError("GpuTimer::end() without a matching begin()");
    Pending* p = open_.back();
    open_.pop_back();
    p->end = takeQuery();
    glQueryCounter(p->end, GL_TIMESTAMP);
}

void GpuTimer::finish()
{
    if (!open_.empty())
        throw gl::GlError("GpuTimer::finish() with stage \"" + open_.back()->stage + "\" still open");
    collect(true);
}

// Reads finished stages in submission order, so each stage's list stays in frame order;
// stops at the first result not yet available unless `wait` is set.
void GpuTimer::collect(bool wait)
{
    size_t done = 0;
    for (; done < pending_.size(); ++done) {
        Pending* p = pending_[done].get();
        if (!p->end)
            break;
        if (!wait) {
            GLint available = 0;
            glGetQueryObjectiv(p->end, GL_QUERY_RESULT_AVAILABLE, &available);
            if (!available)
                break;
        }
        // Results of a finished pair are read without a wait (GL_QUERY_RESULT_NO_WAIT: the
        // end query is available, and queries finish in order), so polling during frames
        // never stalls them; finish() waits.
        const GLenum result = wait ? GL_QUERY_RESULT : GL_QUERY_RESULT_NO_WAIT;
        GLuint64 t0 = 0, t1 = 0;
        glGetQueryObjectui64v(p->begin, result, &t0);
        glGetQueryObjectui64v(p->end, result, &t1);
        stages_[p->stage].ms.push_back(t1 > t0 ? double(t1 - t0) * 1e-6 : 0.0);
        freeQueries_.push_back(std::move(p->begin));
        freeQueries_.push_back(std::move(p->end));
    }
    pending_.erase(pending_.begin(), pending_.begin() + std::ptrdiff_t(done));
}

} // namespace lfd::player
