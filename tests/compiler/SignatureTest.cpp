// SPDX-License-Identifier: GPL-3.0-or-later
#include "compiler/Signature.h"
#include "compiler/Compiler.h"
#include "compiler/ImageCodec.h"
#include "project/ProjectFile.h"

#include "TextEdit.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace rs;

namespace {

using rs::test::replaced;

const char* kTwoUnits = "$name Two units\n"
                        "! id_pluto:00=000000000000\n"
                        "! type_pluto:00=A20,is3\n"
                        "! id_pluto:01=000000000001\n"
                        "! type_pluto:01=A20,is3\n"
                        "! pgm_pluto:00\n"
                        "! I0.0,a_pulse,non_inv\n"
                        "! Q0.10,a_pulse\n"
                        "! I0.1=Start\n"
                        "S0.0_0\n"
                        "Q0.2 = I0.0 * Start     ; the motor\n"
                        "M0.1 = I0.2 + /I0.3\n"
                        "! pgm_pluto:01\n"
                        "S1.0_0\n"
                        "Q1.2 = I1.0 * I1.1\n";

compiler::CompileResult compiled(const std::string& text) {
    compiler::CompileResult result = compiler::compileText(text);
    EXPECT_EQ(result.errors(), 0) << (result.diagnostics.empty() ? ""
                                                                 : result.diagnostics[0].message);
    return result;
}

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::vector<std::filesystem::path> projectsToFormat() {
    std::vector<std::filesystem::path> files;
    for (const char* folder : {RUNGSMITH_TEST_DATA "/manual", RUNGSMITH_EXAMPLES})
        for (const auto& entry : std::filesystem::directory_iterator(folder))
            if (entry.path().extension() == ".sps")
                files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

} // namespace

TEST(Signature, OneLinePerUnitAndTheProjectOverThem) {
    const auto result = compiled(kTwoUnits);
    ASSERT_EQ(result.signatures.size(), 2u);
    EXPECT_EQ(result.signatures[0].station, 0);
    EXPECT_EQ(result.signatures[1].station, 1);
    EXPECT_EQ(result.projectSignature, compiler::projectSignature(result.signatures));
    EXPECT_NE(result.signatures[0].value, result.signatures[1].value);
}

TEST(Signature, IsPrintedAsEightHexDigits) {
    EXPECT_EQ(compiler::signatureText(0x1a2b), "00001A2B");
    EXPECT_EQ(compiler::signatureText(0xFFFFFFFF), "FFFFFFFF");
}

TEST(Signature, OneOperandChangesItsUnitOnly) {
    const auto before = compiled(kTwoUnits);
    const auto after = compiled(replaced(kTwoUnits, "M0.1 = I0.2", "M0.1 = I0.4"));
    EXPECT_NE(after.signatures[0], before.signatures[0]);
    EXPECT_EQ(after.signatures[1], before.signatures[1]);
    EXPECT_NE(after.projectSignature, before.projectSignature);
}

TEST(Signature, CommentsNamesDescriptionsAndLayoutChangeNothing) {
    const auto before = compiled(kTwoUnits);
    for (const std::string& text :
         {replaced(kTwoUnits, "; the motor", "; the conveyor motor"),
          replaced(replaced(kTwoUnits, "! I0.1=Start\n", "! I0.1=Go\n"), "* Start", "* Go"),
          replaced(kTwoUnits, "S0.0_0\n", "S0.0_0\n\n; a comment line\n\n"),
          replaced(kTwoUnits, "Q1.2 = I1.0 * I1.1", "   Q1.2   =   I1.0*I1.1"),
          replaced(kTwoUnits, "! id_pluto:00=000000000000\n",
                   "! id_pluto:00=000000000000\n;@unit 00 description=\"Main cabinet\"\n")}) {
        const auto after = compiled(text);
        EXPECT_EQ(after.signatures, before.signatures) << text;
        EXPECT_EQ(after.projectSignature, before.projectSignature) << text;
    }
}

TEST(Signature, IoOptionsExportsAndRemanentVariablesAreBehaviour) {
    const auto before = compiled(kTwoUnits);
    for (const std::string& text :
         {replaced(kTwoUnits, "! I0.0,a_pulse,non_inv", "! I0.0,a_pulse"),
          replaced(kTwoUnits, "! id_pluto:00=000000000000\n",
                   "! id_pluto:00=000000000000\n;@unit 00 remanent=\"R100-R103\"\n"),
          replaced(kTwoUnits, "! id_pluto:00=000000000000\n",
                   "! id_pluto:00=000000000000\n;@var M0.1 export=\"yes\"\n"),
          replaced(kTwoUnits, "type_pluto:00=A20,is3", "type_pluto:00=A20,is2"),
          replaced(kTwoUnits, "type_pluto:00=A20,is3", "type_pluto:00=B20,is3")}) {
        const auto after = compiled(text);
        EXPECT_NE(after.signatures[0], before.signatures[0]) << text;
        EXPECT_EQ(after.signatures[1], before.signatures[1]) << text;
    }
}

TEST(Signature, TheOrderOfIoOptionsIsNoChange) {
    EXPECT_EQ(
        compiled(kTwoUnits).signatures,
        compiled(replaced(kTwoUnits, "I0.0,a_pulse,non_inv", "I0.0,non_inv,a_pulse")).signatures);
}

TEST(Signature, AUnitWithoutCodeHasOne) {
    const auto result =
        compiled(replaced(kTwoUnits, "! pgm_pluto:01\nS1.0_0\nQ1.2 = I1.0 * I1.1\n", ""));
    ASSERT_EQ(result.signatures.size(), 2u);
    EXPECT_EQ(result.images.size(), 1u);
}

TEST(Signature, TheImageCarriesIt) {
    const auto result = compiled(kTwoUnits);
    const auto read = compiler::readHps(compiler::writeHps(result.images));
    ASSERT_TRUE(std::holds_alternative<std::vector<compiler::UnitImage>>(read));
    const auto& images = std::get<std::vector<compiler::UnitImage>>(read);
    ASSERT_EQ(images.size(), 2u);
    for (std::size_t i = 0; i < images.size(); ++i) {
        EXPECT_EQ(compiler::unitSignature(images[i]), result.signatures[i].value);
        EXPECT_EQ(images[i].projectSignature, result.projectSignature);
    }
}

TEST(Signature, ReindentingKeepsTheImageByteForByte) {
    // The image's places are in the canonical text, which spacing and case
    // do not change.
    const std::string moved = replaced(
        replaced(kTwoUnits, "M0.1 = I0.2 + /I0.3", "        M0.1=I0.2+/I0.3"), "S1.0_0", "s1.0_0");
    EXPECT_EQ(compiler::writeHps(compiled(moved).images),
              compiler::writeHps(compiled(kTwoUnits).images));
}

TEST(Signature, FormatKeepsEveryImageAndSignature) {
    int compiledProjects = 0;
    for (const auto& path : projectsToFormat()) {
        const std::string text = readFile(path);
        const compiler::CompileResult original = compiler::compileText(text);
        if (original.errors())
            continue; // the manual's examples of mistakes
        const project::ProjectReadResult read = project::readProject(text);
        ASSERT_TRUE(read.ok()) << path;
        const compiler::CompileResult formatted =
            compiler::compileText(project::writeProject(read.project));
        EXPECT_EQ(compiler::writeHps(formatted.images), compiler::writeHps(original.images))
            << path;
        EXPECT_EQ(formatted.signatures, original.signatures) << path;
        EXPECT_EQ(formatted.projectSignature, original.projectSignature) << path;
        ++compiledProjects;
    }
    EXPECT_GT(compiledProjects, 20);
}

TEST(Signature, AReaderRefusesADamagedVariableList) {
    // Bytes the encoder never writes must not read as an image that encodes
    // to other bytes: a B-slave flag of 2 in an exported variable, with the
    // image's checksum made to match.
    compiler::UnitImage image;
    image.exported.push_back({lang::AddressKind::Memory, 0, 5, -1, false});
    std::vector<std::uint8_t> bytes = compiler::encodeImage(image);
    ASSERT_TRUE(std::holds_alternative<compiler::UnitImage>(compiler::decodeImage(bytes)));
    // After it: the remanent count, the AS-i setup (4 bytes without slaves), the
    // CAN bus cycle time (2), the External communication setting (1), the CRC.
    const std::size_t flag = bytes.size() - 4 - 1 - 2 - 4 - 4 - 6 + 3;
    bytes[flag] = 2;
    const std::uint32_t crc = compiler::crc32(
        std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size() - 4));
    for (int i = 0; i < 4; ++i)
        bytes[bytes.size() - 4 + static_cast<std::size_t>(i)] =
            static_cast<std::uint8_t>(crc >> (8 * i));
    const auto read = compiler::decodeImage(bytes);
    ASSERT_TRUE(std::holds_alternative<compiler::ImageError>(read));
    EXPECT_EQ(std::get<compiler::ImageError>(read).message,
              "an exported or remanent variable is damaged");
}
