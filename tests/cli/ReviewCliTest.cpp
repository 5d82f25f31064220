// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProgramRun.h"
#include "QtPrinting.h"
#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <gtest/gtest.h>

// signature and diff (cli.md, "Verbs for review, change control and project
// work"), run as a reviewer would, on files in a temporary folder.

using rs::test::ProgramRun;
using rs::test::runCli;

// For the messages of failed expectations.
inline std::ostream& operator<<(std::ostream& os, const QString& text) {
    return os << text.toStdString();
}

namespace {

const QByteArray kReviewProject = "$name Review\n"
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

QByteArray replaced(QByteArray text, const QByteArray& from, const QByteArray& to) {
    EXPECT_TRUE(text.contains(from)) << from.toStdString();
    return text.replace(from, to);
}

QStringList exampleProjects() {
    QStringList files;
    for (const QString& folder :
         {QStringLiteral(RUNGSMITH_TEST_DATA "/manual"), QStringLiteral(RUNGSMITH_EXAMPLES)})
        for (const QString& name : QDir(folder).entryList({"*.sps"}, QDir::Files, QDir::Name))
            files << folder + "/" + name;
    return files;
}

// Diffs OLD against NEW, both written to a temporary folder.
ProgramRun diff(const QByteArray& before, const QByteArray& after) {
    QTemporaryDir dir;
    return runCli({"diff", "--no-io-warnings", rs::test::writeFile(dir, "old.sps", before),
                   rs::test::writeFile(dir, "new.sps", after)});
}

} // namespace

TEST(SignatureCli, OneLinePerUnitThenTheProject) {
    QTemporaryDir dir;
    const ProgramRun run = runCli(
        {"signature", "--no-io-warnings", rs::test::writeFile(dir, "p.sps", kReviewProject)});
    EXPECT_EQ(run.exitCode, 0) << run.errText();
    const QStringList lines = run.outText().split('\n', Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 3) << run.outText();
    EXPECT_TRUE(QRegularExpression("^Pluto 00 [0-9A-F]{8}$").match(lines[0]).hasMatch());
    EXPECT_TRUE(QRegularExpression("^Pluto 01 [0-9A-F]{8}$").match(lines[1]).hasMatch());
    EXPECT_TRUE(QRegularExpression("^project [0-9A-F]{8}$").match(lines[2]).hasMatch());
}

TEST(SignatureCli, OneOperandChangesItsUnitOnlyAndACommentNothing) {
    QTemporaryDir dir;
    const auto signature = [&](const QByteArray& text) {
        return runCli({"signature", "--no-io-warnings", rs::test::writeFile(dir, "p.sps", text)})
            .outText()
            .split('\n');
    };
    const QStringList before = signature(kReviewProject);
    const QStringList operand = signature(replaced(kReviewProject, "I0.2 +", "I0.4 +"));
    EXPECT_NE(operand[0], before[0]);
    EXPECT_EQ(operand[1], before[1]);
    EXPECT_NE(operand[2], before[2]);
    EXPECT_EQ(signature(replaced(kReviewProject, "the motor", "the pump")), before);
}

TEST(SignatureCli, FormatKeepsTheImageAndEverySignatureOfEveryExample) {
    QTemporaryDir dir;
    int compared = 0;
    for (const QString& path : exampleProjects()) {
        const ProgramRun original = runCli({"signature", "--no-io-warnings", path});
        if (original.exitCode != 0)
            continue; // the manual's examples of mistakes, or a project of blocks
        const QString formatted = dir.filePath("formatted.sps");
        ASSERT_EQ(runCli({"format", path}, {formatted}).exitCode, 0) << path;
        EXPECT_EQ(runCli({"signature", "--no-io-warnings", formatted}).out, original.out) << path;
        const QString oldImage = dir.filePath("old.hps"), newImage = dir.filePath("new.hps");
        ASSERT_EQ(runCli({"compile", "--no-io-warnings", path, "-o", oldImage}).exitCode, 0);
        ASSERT_EQ(runCli({"compile", "--no-io-warnings", formatted, "-o", newImage}).exitCode, 0);
        EXPECT_EQ(rs::test::readFile(newImage), rs::test::readFile(oldImage)) << path;
        // The image carries the figures of its source: each unit's that has
        // code (only those have an image) and the project's.
        const QStringList fromImage = runCli({"signature", oldImage}).outText().split('\n');
        const QStringList fromSource = original.outText().split('\n');
        for (const QString& line : fromImage)
            EXPECT_TRUE(fromSource.contains(line)) << path << ": " << line;
        EXPECT_EQ(fromImage.size() >= 2 ? fromImage[fromImage.size() - 2] : QString(),
                  fromSource[fromSource.size() - 2])
            << path;
        ++compared;
    }
    EXPECT_GT(compared, 20);
}

TEST(SignatureCli, BadInputIsADiagnosticOrAUsageError) {
    QTemporaryDir dir;
    const QString bad =
        rs::test::writeFile(dir, "bad.sps", replaced(kReviewProject, "I0.2 +", "I0.2 + +"));
    const ProgramRun errors = runCli({"signature", "--no-io-warnings", bad});
    EXPECT_EQ(errors.exitCode, 1);
    EXPECT_EQ(errors.outText(), "");
    EXPECT_TRUE(errors.errText().startsWith(bad + ":12:")) << errors.errText();

    const QString damaged = rs::test::writeFile(dir, "bad.hps", ":10000000ZZ\n");
    const ProgramRun image = runCli({"signature", damaged});
    EXPECT_EQ(image.exitCode, 1);
    EXPECT_TRUE(
        QRegularExpression("^" + QRegularExpression::escape(damaged) + ":\\d+:\\d+: error: ")
            .match(image.errText())
            .hasMatch())
        << image.errText();

    EXPECT_EQ(runCli({"signature", dir.filePath("missing.sps")}).exitCode, 2);
    EXPECT_EQ(runCli({"signature"}).exitCode, 2);
    EXPECT_EQ(runCli({"signature", bad, bad}).exitCode, 2);
}

TEST(DiffCli, IdenticalAndFormattedProjectsHaveNoChangeInBehaviour) {
    const ProgramRun same = diff(kReviewProject, kReviewProject);
    EXPECT_EQ(same.exitCode, 0);
    EXPECT_EQ(same.outText(), "no change in behaviour\n");

    QTemporaryDir dir;
    const QString original = rs::test::writeFile(dir, "p.sps", kReviewProject);
    const ProgramRun formatted = runCli({"format", original});
    ASSERT_EQ(formatted.exitCode, 0);
    const ProgramRun run = diff(kReviewProject, formatted.out);
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_EQ(run.outText(), "no change in behaviour\n");

    const ProgramRun spaced =
        diff(kReviewProject, replaced(kReviewProject, "M0.1 = I0.2 + /I0.3", "   m0.1=i0.2+/I0.3"));
    EXPECT_EQ(spaced.exitCode, 0);
    EXPECT_EQ(spaced.outText(), "no change in behaviour\n");
}

TEST(DiffCli, ACommentIsOnlyText) {
    const ProgramRun run = diff(kReviewProject, replaced(kReviewProject, "the motor", "the pump"));
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_EQ(run.outText(),
              "Pluto 00 comments: changed\nno change in behaviour; only the text changed\n");
}

TEST(DiffCli, AnInsertedNetworkIsOneAddedLine) {
    const ProgramRun run =
        diff(kReviewProject, replaced(kReviewProject, "S0.0_0\n", "S0.0_0\nM0.5 = I0.5\n"));
    EXPECT_EQ(run.exitCode, 1);
    const QStringList lines = run.outText().split('\n', Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 2) << run.outText();
    EXPECT_EQ(lines[0], "Pluto 00 S0.0_0 network 1: added");
    EXPECT_TRUE(lines[1].startsWith("behaviour changed in Pluto 00 (project signature "))
        << lines[1];
}

TEST(DiffCli, AChangedOperandIsOneChangedNetwork) {
    const ProgramRun run =
        diff(kReviewProject, replaced(kReviewProject, "I1.0 * I1.1", "I1.0 * I1.2"));
    EXPECT_EQ(run.exitCode, 1);
    const QStringList lines = run.outText().split('\n', Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 2) << run.outText();
    EXPECT_EQ(lines[0], "Pluto 01 S1.0_0 network 1: changed");
    EXPECT_TRUE(lines[1].startsWith("behaviour changed in Pluto 01 (")) << lines[1];
}

TEST(DiffCli, AChangedIoOptionIsItsOwnLine) {
    const ProgramRun run =
        diff(kReviewProject, replaced(kReviewProject, "a_pulse,non_inv", "a_pulse"));
    EXPECT_EQ(run.exitCode, 1);
    const QStringList lines = run.outText().split('\n', Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 2) << run.outText();
    EXPECT_EQ(lines[0], "Pluto 00 I/O options: changed");
    EXPECT_TRUE(lines[1].startsWith("behaviour changed in Pluto 00 (")) << lines[1];
}

TEST(DiffCli, AProjectWithErrorsCannotBeCompared) {
    QTemporaryDir dir;
    const QString good = rs::test::writeFile(dir, "good.sps", kReviewProject);
    const QString bad =
        rs::test::writeFile(dir, "bad.sps", replaced(kReviewProject, "I0.2 +", "I0.2 + +"));
    const ProgramRun run = runCli({"diff", "--no-io-warnings", good, bad});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.outText(), "");
    EXPECT_TRUE(run.errText().startsWith(bad + ":12:")) << run.errText();
    EXPECT_TRUE(run.errText().contains("behaviour cannot be compared")) << run.errText();

    EXPECT_EQ(runCli({"diff", good, dir.filePath("missing.sps")}).exitCode, 2);
    EXPECT_EQ(runCli({"diff", good}).exitCode, 2);
}

TEST(ValidateCli, AValidatedProjectReviewsAsUnchangedUntilItChanges) {
    QTemporaryDir dir;
    const QString project = rs::test::writeFile(dir, "p.sps", kReviewProject);
    const QString validated = dir.filePath("validated.sps");
    const ProgramRun validate =
        runCli({"validate", "--no-io-warnings", project, "--by", "A. Reviewer", "--comment",
                "Release 1, report R-17", "--date", "2026-12-01", "-o", validated});
    ASSERT_EQ(validate.exitCode, 0) << validate.errText();
    EXPECT_EQ(rs::test::readFile(project), kReviewProject); // the input is not touched

    const ProgramRun review = runCli({"review", "--no-io-warnings", validated});
    EXPECT_EQ(review.exitCode, 0) << review.errText();
    EXPECT_EQ(review.outText(), "validated on 2026-12-01 by A. Reviewer: Release 1, report R-17\n"
                                "no change in behaviour\n");
    // Validation changes no signature.
    EXPECT_EQ(runCli({"signature", "--no-io-warnings", validated}).out,
              runCli({"signature", "--no-io-warnings", project}).out);

    QByteArray text = rs::test::readFile(validated);
    const QString changed = rs::test::writeFile(
        dir, "changed.sps", replaced(text, "M0.1 = I0.2 + /I0.3\n", "M0.1 = I0.2 + /I0.4\n"));
    const ProgramRun after = runCli({"review", "--no-io-warnings", changed});
    EXPECT_EQ(after.exitCode, 1);
    const QStringList lines = after.outText().split('\n', Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 3) << after.outText();
    EXPECT_EQ(lines[1], "Pluto 00 S0.0_0 network 2: changed");
    EXPECT_TRUE(lines[2].startsWith("behaviour changed in Pluto 00 (")) << lines[2];
}

TEST(ValidateCli, BadInputIsRefusedWithoutWriting) {
    QTemporaryDir dir;
    const QString project = rs::test::writeFile(dir, "p.sps", kReviewProject);
    const QString out = dir.filePath("out.sps");
    EXPECT_EQ(runCli({"validate", project, "-o", out}).exitCode, 2);   // no --by
    EXPECT_EQ(runCli({"validate", project, "--by", "X"}).exitCode, 2); // no -o
    EXPECT_EQ(runCli({"validate", project, "--by", "X", "--date", "1.12.2026", "-o", out}).exitCode,
              2);
    const QString bad =
        rs::test::writeFile(dir, "bad.sps", replaced(kReviewProject, "I0.2 +", "I0.2 + +"));
    const ProgramRun errors = runCli({"validate", bad, "--by", "X", "-o", out});
    EXPECT_EQ(errors.exitCode, 1);
    EXPECT_TRUE(errors.errText().startsWith(bad + ":12:")) << errors.errText();
    EXPECT_FALSE(QFile::exists(out));

    const ProgramRun never = runCli({"review", "--no-io-warnings", project});
    EXPECT_EQ(never.exitCode, 1);
    EXPECT_TRUE(never.errText().contains("has not been validated")) << never.errText();

    const QString broken = rs::test::writeFile(
        dir, "broken.sps",
        replaced(kReviewProject, "$name Review\n", "$name Review\n;@validated signature=\"1\"\n"));
    const ProgramRun record = runCli({"review", broken});
    EXPECT_EQ(record.exitCode, 1);
    EXPECT_TRUE(record.errText().startsWith(broken + ":2:")) << record.errText();
}

TEST(DiffCli, PdfDrawsTheReviewAndKeepsTheExitStatus) {
    QTemporaryDir dir;
    const QString before = rs::test::writeFile(dir, "old.sps", kReviewProject);
    const QString after = rs::test::writeFile(
        dir, "new.sps", replaced(kReviewProject, "S0.0_0\n", "S0.0_0\nM0.5 = I0.5\n"));
    const QString pdf = dir.filePath("review.pdf");
    const ProgramRun run = runCli({"diff", "--no-io-warnings", before, after, "--pdf", pdf});
    EXPECT_EQ(run.exitCode, 1) << run.errText();
    const QByteArray bytes = rs::test::readFile(pdf);
    EXPECT_TRUE(bytes.startsWith("%PDF-")) << bytes.left(16).toStdString();
    // A title page and one page for the one network.
    EXPECT_EQ(bytes.count("/Type /Page\n") + bytes.count("/Type /Page "), 2)
        << bytes.count("/Type /Page");

    const QString nowhere = dir.filePath("missing/review.pdf");
    const ProgramRun unwritable =
        runCli({"diff", "--no-io-warnings", before, after, "--pdf", nowhere});
    EXPECT_EQ(unwritable.exitCode, 2);
    EXPECT_TRUE(unwritable.errText().contains("cannot write " + nowhere)) << unwritable.errText();
    EXPECT_FALSE(QFile::exists(nowhere));
}
