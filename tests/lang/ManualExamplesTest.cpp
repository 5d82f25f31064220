// SPDX-License-Identifier: GPL-3.0-or-later
#include "compiler/Compiler.h"
#include "lang/Lexer.h"
#include "project/ProjectFile.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;
using namespace rs;

namespace {

std::vector<fs::path> manualExamples() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(fs::path(RUNGSMITH_TEST_DATA) / "manual"))
        if (entry.path().extension() == ".sps")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::string readFile(const fs::path& path) {
    auto file = project::readTextFile(QString::fromStdString(path.string()));
    EXPECT_TRUE(file.error.isEmpty()) << file.error.toStdString();
    return file.text;
}

std::vector<std::string> commentsOf(std::string_view text) {
    std::vector<std::string> comments;
    lang::Lexer lexer(text);
    for (auto token = lexer.next(); token.kind != lang::TokenKind::EndOfFile; token = lexer.next())
        if (token.kind == lang::TokenKind::Comment) {
            std::string comment(token.text);
            while (!comment.empty() && (comment.back() == ' ' || comment.back() == '\r'))
                comment.pop_back();
            comments.push_back(comment);
        }
    return comments;
}

class ManualExample : public ::testing::TestWithParam<fs::path> {};

TEST(ManualExamples, AreAllThere) {
    EXPECT_GE(manualExamples().size(), 40u);
}

TEST_P(ManualExample, ParsesFormatsIdempotentlyAndKeepsEveryComment) {
    const std::string source = readFile(GetParam());
    auto first = project::readProject(source);
    for (const auto& d : first.diagnostics)
        ADD_FAILURE() << GetParam().filename() << ":" << d.line << ":" << d.column << ": "
                      << d.message;
    const std::string formatted = project::writeProject(first.project);
    auto second = project::readProject(formatted);
    EXPECT_TRUE(second.diagnostics.empty());
    EXPECT_EQ(project::writeProject(second.project), formatted);
    EXPECT_EQ(commentsOf(formatted), commentsOf(source));
}

TEST_P(ManualExample, CompilesWithoutErrors) {
    auto result = compiler::compileText(readFile(GetParam()));
    for (const auto& d : result.diagnostics)
        if (d.severity == lang::Severity::Error)
            ADD_FAILURE() << GetParam().filename() << ":" << d.line << ":" << d.column << ": "
                          << d.message;
    EXPECT_FALSE(result.images.empty());
}

INSTANTIATE_TEST_SUITE_P(Manuals, ManualExample, ::testing::ValuesIn(manualExamples()),
                         [](const auto& info) {
                             std::string name = info.param.stem().string();
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c)))
                                     c = '_';
                             return name;
                         });

} // namespace
