// SPDX-License-Identifier: GPL-3.0-or-later
#include "compiler/Compiler.h"
#include "compiler/ImageCodec.h"
#include "project/ProjectFile.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

using namespace rs;
using compiler::Op;

namespace {

std::string muting() {
    std::ifstream file(RUNGSMITH_TEST_DATA "/manual/manual_muting.sps");
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

std::vector<compiler::UnitImage> compileOk(const std::string& text) {
    compiler::CompileResult result = compiler::compileText(text);
    EXPECT_EQ(result.errors(), 0) << (result.diagnostics.empty() ? ""
                                                                 : result.diagnostics[0].message);
    return result.images;
}

const char* kSmall = "$name Small\n"
                     "! id_pluto:00=000000000000\n"
                     "! type_pluto:00=A20,is3\n"
                     "! pgm_pluto:00\n"
                     "S0.1_0\n"
                     "J(+1) = I0.3\n"
                     "S0.1_1\n"
                     "J(0) = I0.4\n"
                     "S0.0_0\n"
                     "Q0.1 = I0.0 * (I0.1 + /I0.2) * TON(1s00)\n"
                     "(R0.1 = R0.2 + 5) = P(I0.5)\n";

} // namespace

TEST(Image, InstructionsFollowTheRungLeftToRight) {
    auto images = compileOk(kSmall);
    ASSERT_EQ(images.size(), 1u);
    const auto& image = images[0];
    ASSERT_EQ(image.steps.size(), 3u);
    // The PLC code comes first, whatever the order in the file.
    EXPECT_EQ(image.steps[0].sequence, 0);
    EXPECT_EQ(image.steps[1].sequence, 1);
    EXPECT_EQ(image.steps[2].step, 1);
    std::vector<Op> ops;
    std::vector<int> elements;
    for (std::uint32_t i = image.steps[0].first; i < image.steps[0].first + image.steps[0].count;
         ++i) {
        ops.push_back(image.code[i].op);
        elements.push_back(image.code[i].element);
    }
    EXPECT_EQ(ops,
              (std::vector<Op>{Op::Rung, Op::Contact, Op::BranchOpen, Op::Contact, Op::BranchNext,
                               Op::Contact, Op::BranchClose, Op::Timer, Op::Coil, Op::Rung,
                               Op::Edge, Op::LoadA, Op::LoadB, Op::Arith}));
    // Element numbers: 0 the output, then the expression's nodes in pre-order.
    EXPECT_EQ(elements, (std::vector<int>{0, 2, 3, 4, 3, 5, 3, 6, 0, 0, 1, 0, 0, 0}));
    const auto& negated = image.code[image.steps[0].first + 5];
    EXPECT_TRUE(negated.flags & compiler::Negated);
    EXPECT_EQ(negated.line, 10u);
    EXPECT_EQ(negated.statement, 2u); // the jumps above it in the file are statements 0 and 1
    EXPECT_EQ(image.timers, 1);
    EXPECT_EQ(image.edges, 1);
    const auto& jump = image.code[image.steps[1].first + 2];
    EXPECT_EQ(jump.op, Op::Jump);
    EXPECT_EQ(jump.slot, 1); // J(+1) from step 0
}

TEST(Image, EncodingRoundTripsAndIsDeterministic) {
    auto images = compileOk(muting());
    ASSERT_EQ(images.size(), 1u);
    EXPECT_EQ(images[0].projectName, "Example, manual");
    const std::string hps = compiler::writeHps(images);
    auto read = compiler::readHps(hps);
    ASSERT_TRUE(std::holds_alternative<std::vector<compiler::UnitImage>>(read))
        << std::get<compiler::ImageError>(read).message;
    EXPECT_TRUE(std::get<std::vector<compiler::UnitImage>>(read) == images);
    EXPECT_EQ(compiler::writeHps(compileOk(muting())), hps);
}

TEST(Image, SpellingDoesNotChangeTheImage) {
    // The same program in other case and spacing: the same lines, the same bytes.
    std::string source = muting();
    std::string shouted = source;
    for (char& c : shouted)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    EXPECT_EQ(compiler::writeHps(compileOk(shouted)).size(),
              compiler::writeHps(compileOk(source)).size());
    std::string spaced = source;
    for (std::size_t at = spaced.find(" * "); at != std::string::npos;
         at = spaced.find(" * ", at + 1))
        spaced.replace(at, 3, "*");
    EXPECT_EQ(compiler::writeHps(compileOk(spaced)), compiler::writeHps(compileOk(source)));
}

TEST(Image, ProjectCrcTellsProjectsApart) {
    auto a = compileOk(kSmall);
    std::string other = kSmall;
    other.replace(other.find("Small"), 5, "Other");
    auto b = compileOk(other);
    EXPECT_NE(a[0].sourceCrc, b[0].sourceCrc);
    EXPECT_EQ(a[0].sourceCrc,
              compiler::crc32(project::writeProject(project::readProject(kSmall).project)));
}

TEST(Image, IncludedSourceComesBack) {
    std::string text = std::string(kSmall);
    text.insert(text.find('\n') + 1, ";@project include_source=yes\n");
    auto images = compileOk(text);
    ASSERT_EQ(images.size(), 1u);
    EXPECT_EQ(images[0].source, project::writeProject(project::readProject(text).project));
    auto read = compiler::readHps(compiler::writeHps(images));
    EXPECT_EQ(std::get<std::vector<compiler::UnitImage>>(read)[0].source, images[0].source);
    EXPECT_TRUE(compileOk(kSmall)[0].source.empty());
}

TEST(Image, EveryUnitIsStoredAtItsStation) {
    const char* two = "! id_pluto:03=000000000000\n"
                      "! id_pluto_Double:12=000000000000\n"
                      "! pgm_pluto:12\nS12.0_0\nQ12.4 = I3.0\n"
                      "! pgm_pluto:03\nS3.0_0\nQ3.0 = I12.1\n";
    auto images = compileOk(two);
    ASSERT_EQ(images.size(), 2u);
    const std::string hps = compiler::writeHps(images);
    EXPECT_NE(hps.find(":020000040300F7\n"), std::string::npos); // unit 3 at 0x3000000
    EXPECT_NE(hps.find(":020000040C00EE\n"), std::string::npos); // unit 12 at 0xC000000
    auto read = std::get<std::vector<compiler::UnitImage>>(compiler::readHps(hps));
    ASSERT_EQ(read.size(), 2u);
    EXPECT_EQ(read[0].station, 3);
    EXPECT_EQ(read[1].station, 12);
    EXPECT_EQ(read[1].unitType, static_cast<int>(target::UnitType::B46));
}

TEST(Image, DamageIsReportedWithItsLine) {
    std::string hps = compiler::writeHps(compileOk(muting()));
    std::size_t third = hps.find('\n', hps.find('\n') + 1) + 1;
    hps[third + 12] = hps[third + 12] == '0' ? '1' : '0';
    auto read = compiler::readHps(hps);
    ASSERT_TRUE(std::holds_alternative<compiler::ImageError>(read));
    EXPECT_EQ(std::get<compiler::ImageError>(read).line, 3);
}

TEST(Image, DamagedBytesAreRejected) {
    auto images = compileOk(kSmall);
    auto bytes = compiler::encodeImage(images[0]);
    bytes[20] ^= 0x40;
    auto result = compiler::decodeImage(bytes);
    ASSERT_TRUE(std::holds_alternative<compiler::ImageError>(result));
    EXPECT_EQ(std::get<compiler::ImageError>(result).message,
              "the image is damaged (its checksum does not match)");
    std::vector<std::uint8_t> foreign = {'N', 'O', 'P', 'E', 0, 0, 0, 0};
    EXPECT_EQ(std::get<compiler::ImageError>(compiler::decodeImage(foreign)).message,
              "not a Rungsmith image (it does not start with RSIM)");
}

TEST(Image, ProjectsWithErrorsGiveNoImage) {
    auto result =
        compiler::compileText("! id_pluto:00=000000000000\n! pgm_pluto:00\nS0.0_0\nJ(1)\n");
    EXPECT_EQ(result.errors(), 1);
    EXPECT_TRUE(result.images.empty());
}

// The engine indexes its tables with a timer's kind, a comparison and an
// arithmetic operation: an image that names one it does not know is refused
// when read, whatever its checksum says.
TEST(Image, UnknownVariantsOfAnInstructionAreRejected) {
    const auto images = compileOk("! id_pluto:00=000000000000\n! pgm_pluto:00\nS0.0_0\n"
                                  "Q0.0 = TON(0s50) * (R0.1 > 5)\n(R0.2 += 1) = I0.1\n");
    int tried = 0;
    for (std::size_t i = 0; i < images[0].code.size(); ++i) {
        const compiler::Op op = images[0].code[i].op;
        if (op != compiler::Op::Timer && op != compiler::Op::Compare && op != compiler::Op::Arith)
            continue;
        auto damaged = images[0];
        damaged.code[i].aux = 200;
        const auto result = compiler::decodeImage(compiler::encodeImage(damaged));
        ASSERT_TRUE(std::holds_alternative<compiler::ImageError>(result));
        EXPECT_EQ(std::get<compiler::ImageError>(result).message,
                  "unknown variant 200 of instruction " + std::to_string(int(op)));
        ++tried;
    }
    EXPECT_EQ(tried, 3);
}

// The compiler measures an image by encoding it only when this bound passes
// the limit, so the bound must never be below the real size.
TEST(Image, TheSizeBoundIsNeverBelowTheEncodedSize) {
    for (const std::string& text : {std::string(muting()), std::string(kSmall),
                                    std::string(kSmall).insert(std::string(kSmall).find('\n') + 1,
                                                               ";@project include_source=yes\n")})
        for (const auto& image : compileOk(text))
            EXPECT_GE(compiler::encodedSizeBound(image), compiler::encodeImage(image).size());
}
