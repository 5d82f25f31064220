// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "output/CompileOutputModel.h"

#include <QTreeView>

namespace rs::compiler {
struct CompileResult;
}
namespace rs::project {
struct TextPlace;
}

namespace rs::ui {

// The output of Build > Compile (manual Part 1, 13): a line per finding with
// where it is (a unit's code and line, a unit's settings, a variable) and the
// closing line "N Error(s) detected Result=OK|FAILED". Activating a finding
// asks for its place to be shown.
class CompileOutput : public QTreeView {
    Q_OBJECT
public:
    using Column = CompileOutputModel::Column;
    static constexpr Column PlaceColumn = CompileOutputModel::PlaceColumn;
    static constexpr Column MessageColumn = CompileOutputModel::MessageColumn;

    explicit CompileOutput(QWidget* parent = nullptr);

    void showRunning(const QString& projectName);
    // The findings of compiling a project's canonical text, which the lines
    // count in, and the compiled file written or why it could not be.
    void showResult(const QString& projectName, std::string_view canonicalText,
                    const compiler::CompileResult& result, const QString& writtenFile,
                    const QString& writeError = {});
    void clear();
    QString closingLine() const;

    // The rows as shown.
    int rowCount() const;
    QString text(int row, Column column) const;

signals:
    void placeActivated(const project::TextPlace& place, int column);

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    CompileOutputModel* m_model;
};

} // namespace rs::ui
