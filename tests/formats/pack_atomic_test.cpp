// writePack is atomic: a failed write leaves neither a partial pack nor a temporary file,
// and never damages a file already at the target path.
#include "pack_test_scenes.h"

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;

class PackAtomicWrite : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir_ = fs::temp_directory_path() /
               ("lfd_pack_atomic_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::vector<std::string> entries() const
    {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(dir_))
            names.push_back(e.path().filename().string());
        return names;
    }

    static void writeText(const fs::path& path, const std::string& text)
    {
        std::ofstream(path, std::ios::binary) << text;
    }
    static std::string readText(const fs::path& path)
    {
        std::ifstream in(path, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    }

    fs::path dir_;
};

TEST_F(PackAtomicWrite, MissingDirectoryThrowsAndCreatesNothing)
{
    const fs::path path = dir_ / "missing" / "scene.lfdpack";
    try {
        writePack(path, makeFullScene());
        FAIL() << "expected PackError";
    } catch (const PackError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.find('\n'), std::string::npos);
        EXPECT_EQ(what.rfind(path.string() + ": ", 0), 0u) << what;
    }
    EXPECT_FALSE(fs::exists(dir_ / "missing"));
    EXPECT_TRUE(entries().empty());
}

TEST_F(PackAtomicWrite, ThrowingProducerLeavesNoFile)
{
    const Scene eager = makeFullScene();
    const fs::path path = dir_ / "scene.lfdpack";
    bool producedFirst = false;
    const TextureProducer produce = [&](uint32_t i) -> Texture {
        if (i == 1) {
            // The temporary file exists mid-write (texture 0 and the sections before it
            // were written), so removing it is really tested.
            EXPECT_EQ(entries().size(), 1u);
            throw std::runtime_error("out of memory decoding texture");
        }
        producedFirst = true;
        return eager.textures[i];
    };
    EXPECT_THROW(writePack(path, withoutTexels(eager), produce), PackError);
    EXPECT_TRUE(producedFirst);
    EXPECT_TRUE(entries().empty()); // neither the pack nor its temporary
}

TEST_F(PackAtomicWrite, FailedWriteLeavesExistingFileIntact)
{
    const fs::path path = dir_ / "scene.lfdpack";
    writeText(path, "previous pack contents");
    const Scene eager = makeFullScene();

    // A producer failure mid-write...
    const TextureProducer failing = [&](uint32_t i) -> Texture {
        if (i == 1)
            throw std::runtime_error("disk on fire");
        return eager.textures[i];
    };
    EXPECT_THROW(writePack(path, withoutTexels(eager), failing), PackError);
    EXPECT_EQ(readText(path), "previous pack contents");

    // ...a produced texture that does not match its metadata...
    const TextureProducer wrongSize = [&](uint32_t i) {
        Texture t = eager.textures[i];
        t.texels.push_back(0);
        return t;
    };
    EXPECT_THROW(writePack(path, withoutTexels(eager), wrongSize), PackError);
    EXPECT_EQ(readText(path), "previous pack contents");

    // ...and an invalid scene all leave the old file alone.
    Scene invalid = eager;
    invalid.indices[0] = 1000;
    EXPECT_THROW(writePack(path, invalid), PackError);
    EXPECT_EQ(readText(path), "previous pack contents");
    EXPECT_EQ(entries(), std::vector<std::string>{"scene.lfdpack"});
}

TEST_F(PackAtomicWrite, SuccessfulWriteReplacesExistingFile)
{
    const fs::path path = dir_ / "scene.lfdpack";
    writeText(path, "previous pack contents");
    const Scene scene = makeFullScene();
    writePack(path, scene);
    expectSameScene(scene, readPack(path));
    EXPECT_EQ(entries(), std::vector<std::string>{"scene.lfdpack"});
}

TEST_F(PackAtomicWrite, ReadErrorsNameTheFile)
{
    const fs::path missing = dir_ / "nope.lfdpack";
    try {
        readPack(missing);
        FAIL() << "expected PackError";
    } catch (const PackError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(missing.string() + ": cannot open", 0), 0u) << e.what();
    }
    EXPECT_THROW(verifyPack(dir_), PackError); // a directory is not a pack

    // A corrupt file on disk: both readPack and verifyPack name it.
    const fs::path corrupt = dir_ / "corrupt.lfdpack";
    writePack(corrupt, makeFullScene());
    std::string bytes = readText(corrupt);
    bytes[bytes.size() - 1] ^= 0x40;
    writeText(corrupt, bytes);
    for (const bool verify : {false, true}) {
        try {
            verify ? (void)verifyPack(corrupt) : (void)readPack(corrupt);
            ADD_FAILURE() << "corrupt pack accepted";
        } catch (const PackError& e) {
            const std::string what = e.what();
            // The last section is MIPS (texture and mip records follow the texels).
            EXPECT_EQ(what, corrupt.string() + ": section 'MIPS' checksum mismatch (corrupt payload)");
        }
    }
}

} // namespace
} // namespace lfd::test
