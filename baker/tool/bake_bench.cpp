// lfd-bake --bench (see bake_bench.h and docs/baker/throughput.md).
//
// The scene: 8 grid meshes (one node each, side by side), gently curved so that no two
// triangles are alike, with normals and uvs, one material with one square sRGB texture.
// The edge bound is 1.2 grid cells: every quad's diagonal (1.41 cells) is over it and its
// sides are not, so every input triangle is welded, rated and cut in two - the splitting
// path for every triangle, not just the edge scan that leaves small triangles alone.
//
// The texture's mip chain is built from a procedural level 0 at the full requested size
// (a bake would keep a 16384² texture whole only with --keep-full-textures or a scene the
// views see that finely: texture_budget.cpp). Decoding is left out on purpose: it is
// OpenImageIO's work, one thread per image (with threads, textures overlap each other:
// texture_prefetch.h), and one generated texture would not show that.
#include "bake_bench.h"

#include "bake_log.h"
#include "tessellation.h"
#include "triangle_stats.h"
#include "mip_chain.h"
#include "parallel.h"
#include "texture_compression.h"

#include "lfd/pack_layout.h"

#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <sstream>
#include <string>

namespace lfd::bake {
namespace {

constexpr uint32_t kMeshes = 8;
constexpr double kBoundInCells = 1.2;

using Clock = std::chrono::steady_clock;

// Wall-clock and CPU time (user + system, every thread of the process) of one stage.
// CPU time over wall time is how many cores the stage kept busy: on a machine shared with
// other work, a stage that runs on 2 threads may get less than 2 cores, and the ratio
// tells that apart from a stage that did not use its threads.
struct StageTimer {
    Clock::time_point wall = Clock::now();
    double cpu = cpuSeconds();

    static double cpuSeconds()
    {
        rusage usage{};
        getrusage(RUSAGE_SELF, &usage);
        return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
               1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
    }
    void stop(double& wallSeconds, double& cores) const
    {
        wallSeconds = std::chrono::duration<double>(Clock::now() - wall).count();
        cores = wallSeconds > 0.0 ? (cpuSeconds() - cpu) / wallSeconds : 0.0;
    }
};

// What one run measured; crosses from the child process as one line of text.
struct RunResult {
    uint64_t trianglesIn = 0;
    uint64_t trianglesOut = 0;
    double tessellationSeconds = 0.0, tessellationCores = 0.0;
    double statisticsSeconds = 0.0, statisticsCores = 0.0;
    double mipSeconds = 0.0, mipCores = 0.0;
    double compressSeconds = 0.0, compressCores = 0.0; // the chain to BC1 (colour's format)
    uint64_t level0Pixels = 0;
    uint64_t peakRssBytes = 0;
    uint64_t outputHash = 0; // of every byte the stages produced
    std::string error;       // empty: the run succeeded
};

constexpr const char* kRunTag = "lfd-bake-bench-run";

std::string toLine(const RunResult& r)
{
    std::ostringstream line;
    line << std::setprecision(17) << kRunTag << " " << r.trianglesIn << " " << r.trianglesOut << " "
         << r.tessellationSeconds << " " << r.tessellationCores << " " << r.statisticsSeconds << " "
         << r.statisticsCores << " " << r.mipSeconds << " " << r.mipCores << " " << r.compressSeconds << " "
         << r.compressCores << " " << r.level0Pixels << " "
         << r.peakRssBytes << " " << r.outputHash;
    return line.str();
}

bool fromLine(const std::string& text, RunResult& r)
{
    std::istringstream line(text);
    std::string tag;
    line >> tag >> r.trianglesIn >> r.trianglesOut >> r.tessellationSeconds >> r.tessellationCores >>
        r.statisticsSeconds >> r.statisticsCores >> r.mipSeconds >> r.mipCores >> r.compressSeconds >>
        r.compressCores >> r.level0Pixels >>
        r.peakRssBytes >> r.outputHash;
    return tag == kRunTag && !line.fail();
}

// Quads along each side of a mesh's grid, for about `triangles` in all.
uint32_t gridSize(size_t triangles)
{
    return uint32_t(std::max(1.0, std::round(std::sqrt(double(triangles) / (2.0 * kMeshes)))));
}

// n x n quads per mesh, cell size 1 / n. Returns the scene and sets `bound` (scene units).
Scene benchScene(size_t triangles, uint32_t textureSize, double& bound)
{
    const uint32_t n = gridSize(triangles);
    const double cell = 1.0 / n;
    bound = kBoundInCells * cell;

    Scene scene;
    Texture texture;
    texture.name = "bench";
    texture.width = texture.sourceWidth = textureSize;
    texture.height = texture.sourceHeight = textureSize;
    texture.srgb = true;
    scene.textures.push_back(texture);
    Material material;
    material.name = "bench";
    material.baseColorTexture = 0;
    scene.materials.push_back(material);

    VertexStreams& v = scene.vertices;
    for (uint32_t m = 0; m < kMeshes; ++m) {
        // Height field z = a sin(kx x + phase) cos(ky y): slopes stay under 0.25, so the
        // quad sides stay within 3% of a cell and under the bound.
        const double a = 0.01, kx = 2.0 * 3.14159265358979 * (2 + m % 3), ky = 2.0 * 3.14159265358979 * 3;
        const double phase = 0.7 * m;
        const auto base = uint32_t(v.positions.size());
        for (uint32_t j = 0; j <= n; ++j)
            for (uint32_t i = 0; i <= n; ++i) {
                const double x = i * cell, y = j * cell;
                const double z = a * std::sin(kx * x + phase) * std::cos(ky * y);
                const double dzdx = a * kx * std::cos(kx * x + phase) * std::cos(ky * y);
                const double dzdy = -a * ky * std::sin(kx * x + phase) * std::sin(ky * y);
                v.positions.emplace_back(float(x), float(y), float(z));
                v.normals.push_back(glm::normalize(glm::vec3(float(-dzdx), float(-dzdy), 1.0f)));
                v.uvs.emplace_back(float(x), float(y));
            }
        Primitive prim;
        prim.firstIndex = uint32_t(scene.indices.size());
        prim.material = 0;
        for (uint32_t j = 0; j < n; ++j)
            for (uint32_t i = 0; i < n; ++i) {
                const uint32_t c = base + j * (n + 1) + i;
                for (uint32_t index : {c, c + 1, c + n + 2, c, c + n + 2, c + n + 1})
                    scene.indices.push_back(index);
            }
        prim.indexCount = uint32_t(scene.indices.size()) - prim.firstIndex;
        scene.primitives.push_back(prim);
        Mesh mesh;
        mesh.name = "grid " + std::to_string(m);
        mesh.firstPrimitive = m;
        mesh.primitiveCount = 1;
        scene.meshes.push_back(mesh);
        Node node;
        node.name = mesh.name;
        node.mesh = int32_t(m);
        node.translation = glm::vec3(1.1f * float(m), 0.0f, 0.0f);
        scene.nodes.push_back(node);
    }
    return scene;
}

// Level 0 of the chain: a pattern with detail at every scale, so no level is flat.
void fillLevel0(uint8_t* texels, uint32_t size, unsigned threads)
{
    parallelFor(size, threads, [&](size_t y) {
        uint8_t* row = texels + y * size * 4;
        for (uint32_t x = 0; x < size; ++x) {
            const uint32_t h = uint32_t(x * 0x9E3779B1u ^ uint32_t(y) * 0x85EBCA77u);
            row[4 * x + 0] = uint8_t(x ^ y);
            row[4 * x + 1] = uint8_t((x + 2 * y) >> 3);
            row[4 * x + 2] = uint8_t(h >> 24);
            row[4 * x + 3] = uint8_t(255 - ((x * y) >> 12));
        }
    });
}

template <typename T>
uint64_t hashOf(const std::vector<T>& values, uint64_t previous)
{
    return pack::checksum(values.data(), values.size() * sizeof(T)) ^ (previous * 0x9E3779B97F4A7C15ull);
}

// One run: the three stages with `threads` threads, timed.
// Keeps the fastest of a stage's repetitions (and how many cores it kept busy).
struct Fastest {
    double seconds = 0.0, cores = 0.0;
    bool any = false;

    void add(double s, double c)
    {
        if (!any || s < seconds) {
            seconds = s;
            cores = c;
        }
        any = true;
    }
};

// One run: the three stages with `threads` threads, each repeated and timed.
RunResult runOnce(const BenchOptions& options, unsigned threads)
{
    RunResult r;
    Fastest tessellation, statistics, mips, compression;
    double bound = 0.0;
    Scene scene;
    for (unsigned k = 0; k < options.repeat; ++k) {
        scene = benchScene(options.triangles, options.textureSize, bound);
        r.trianglesIn = scene.triangleCount();
        double seconds = 0.0, cores = 0.0;
        const StageTimer tessellationTimer;
        tessellateScene(scene, bound, Log{}, threads);
        tessellationTimer.stop(seconds, cores);
        tessellation.add(seconds, cores);
        r.trianglesOut = scene.triangleCount();

        const StageTimer statisticsTimer;
        computeTriangleStats(scene, threads);
        statisticsTimer.stop(seconds, cores);
        statistics.add(seconds, cores);
    }

    // Every repetition rebuilds the same chain from the same level 0 in the same buffer.
    const std::vector<MipLevel> levels = mip::chainLayout(options.textureSize, options.textureSize);
    std::vector<uint8_t> texels(mip::chainBytes(levels));
    fillLevel0(texels.data(), options.textureSize, threads);
    for (unsigned k = 0; k < options.repeat; ++k) {
        double seconds = 0.0, cores = 0.0;
        const StageTimer mipTimer;
        mip::buildChain(texels.data(), levels, true, threads);
        mipTimer.stop(seconds, cores);
        mips.add(seconds, cores);
    }
    // Block compression of the finished chain, as the bake does for a colour texture.
    Texture chain;
    chain.width = chain.height = options.textureSize;
    chain.srgb = true;
    chain.mips = levels;
    chain.texels = std::move(texels);
    std::vector<uint8_t> blocks;
    for (unsigned k = 0; k < options.repeat; ++k) {
        double seconds = 0.0, cores = 0.0;
        ThreadBudget budget(threads);
        const StageTimer compressTimer;
        blocks = compressChain(chain, TextureFormat::Bc1, kUseColour, budget);
        compressTimer.stop(seconds, cores);
        compression.add(seconds, cores);
    }
    texels = std::move(chain.texels);
    r.compressSeconds = compression.seconds;
    r.compressCores = compression.cores;
    r.level0Pixels = uint64_t(options.textureSize) * options.textureSize;
    r.tessellationSeconds = tessellation.seconds;
    r.tessellationCores = tessellation.cores;
    r.statisticsSeconds = statistics.seconds;
    r.statisticsCores = statistics.cores;
    r.mipSeconds = mips.seconds;
    r.mipCores = mips.cores;

    uint64_t hash = 0;
    hash = hashOf(scene.vertices.positions, hash);
    hash = hashOf(scene.vertices.normals, hash);
    hash = hashOf(scene.vertices.uvs, hash);
    hash = hashOf(scene.indices, hash);
    hash = hashOf(scene.triangleStats, hash);
    hash = hashOf(texels, hash);
    hash = hashOf(blocks, hash);
    r.outputHash = hash;

    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    r.peakRssBytes = uint64_t(usage.ru_maxrss) * 1024; // Linux reports KiB
    return r;
}

// One run in a fresh process (this executable again, with --bench-run): its ru_maxrss is
// this run's peak alone, not the highest of all runs so far as it would be in one
// process. (Not fork(): the libraries lfd-bake loads start threads of their own, and a
// forked copy of a multi-threaded process must not start threads.)
RunResult runInChild(const BenchOptions& options, unsigned threads)
{
    RunResult r;
    int fds[2];
    if (pipe(fds) != 0) {
        r.error = std::string("cannot create a pipe: ") + std::strerror(errno);
        return r;
    }
    const std::string arguments[] = {"lfd-bake",
                                     "--bench-run",
                                     std::to_string(threads),
                                     "--bench-triangles",
                                     std::to_string(options.triangles),
                                     "--bench-texture-size",
                                     std::to_string(options.textureSize),
                                     "--bench-repeat",
                                     std::to_string(options.repeat)};
    std::vector<char*> argv;
    for (const std::string& a : arguments)
        argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    pid_t pid = -1;
    const int spawned = posix_spawn(&pid, "/proc/self/exe", &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    if (spawned != 0) {
        close(fds[0]);
        r.error = std::string("cannot start a bench run: ") + std::strerror(spawned);
        return r;
    }
    std::string output;
    char buffer[4096];
    for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) > 0;)
        output.append(buffer, size_t(n));
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (!fromLine(output, r)) {
        r = RunResult{};
        while (!output.empty() && output.back() == '\n')
            output.pop_back();
        r.error = output.empty() ? "the run ended without a result (" +
                                       std::string(WIFSIGNALED(status) ? "signal " : "exit status ") +
                                       std::to_string(WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status)) + ")"
                                 : output;
    }
    return r;
}

double perSecond(double amount, double seconds) { return seconds > 0.0 ? amount / seconds : 0.0; }

} // namespace

int runBench(const BenchOptions& options, std::ostream& out)
{
    const uint64_t n = gridSize(options.triangles);
    out << "lfd-bake --bench: " << kMeshes << " meshes, " << kMeshes * 2 * n * n
        << " triangles (each with one edge over the bound), " << options.textureSize << "x" << options.textureSize
        << " sRGB texture; " << resolveThreads(0) << " hardware threads; fastest of " << options.repeat
        << (options.repeat == 1 ? " repetition" : " repetitions") << " per stage\n"
        << std::flush; // shown while the runs work

    std::vector<RunResult> runs;
    for (unsigned threads : options.threads) {
        const RunResult r = runInChild(options, threads);
        if (!r.error.empty()) {
            out << "lfd-bake: error: bench with " << threads << " threads: " << r.error << "\n";
            return 1;
        }
        out << std::fixed << "threads " << threads << ": tessellation " << r.trianglesIn << " -> " << r.trianglesOut
            << " triangles in " << std::setprecision(4) << r.tessellationSeconds << " s = " << std::setprecision(3)
            << perSecond(double(r.trianglesIn) / 1e6, r.tessellationSeconds) << " Mtri/s (" << std::setprecision(2)
            << r.tessellationCores << " cores); statistics " << r.trianglesOut << " triangles in "
            << std::setprecision(4) << r.statisticsSeconds << " s = " << std::setprecision(3)
            << perSecond(double(r.trianglesOut) / 1e6, r.statisticsSeconds) << " Mtri/s (" << std::setprecision(2)
            << r.statisticsCores << " cores); mips " << std::setprecision(1) << double(r.level0Pixels) / 1e6
            << " MP in " << std::setprecision(4) << r.mipSeconds << " s = " << std::setprecision(1)
            << perSecond(double(r.level0Pixels) / 1e6, r.mipSeconds) << " MP/s (" << std::setprecision(2)
            << r.mipCores << " cores); BC1 compression " << std::setprecision(1) << double(r.level0Pixels) / 1e6
            << " MP in " << std::setprecision(4) << r.compressSeconds << " s = " << std::setprecision(1)
            << perSecond(double(r.level0Pixels) / 1e6, r.compressSeconds) << " MP/s (" << std::setprecision(2)
            << r.compressCores << " cores); peak memory " << std::setprecision(1)
            << double(r.peakRssBytes) / double(1 << 20) << " MiB\n"
            << std::flush;
        runs.push_back(r);
    }

    bool identical = true;
    for (size_t i = 1; i < runs.size(); ++i) {
        const RunResult& a = runs.front();
        const RunResult& b = runs[i];
        out << std::setprecision(2) << "speed-up " << options.threads[i] << " vs " << options.threads.front()
            << " threads: tessellation " << a.tessellationSeconds / b.tessellationSeconds << "x, statistics "
            << a.statisticsSeconds / b.statisticsSeconds << "x, mips " << a.mipSeconds / b.mipSeconds
            << "x, compression " << a.compressSeconds / b.compressSeconds << "x\n";
        identical = identical && b.outputHash == a.outputHash;
    }
    out << "identical output for every thread count: " << (identical ? "yes" : "NO") << "\n";
    return identical ? 0 : 1;
}

int runBenchChild(const BenchOptions& options, unsigned threads, std::ostream& out)
{
    try {
        out << toLine(runOnce(options, threads)) << "\n";
        return 0;
    } catch (const std::exception& e) {
        out << e.what() << "\n";
    } catch (...) {
        out << "unknown exception\n";
    }
    return 1;
}

} // namespace lfd::bake
