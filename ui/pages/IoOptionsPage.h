// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Holds core types by value, so their headers come in here; Qt 6.4's moc cannot
// parse the C++20 standard headers they bring in (<concepts>) and needs only the names.
#ifndef Q_MOC_RUN
#include "project/IoOptions.h"
#endif

#include <QPointer>
#include <QWidget>

#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;
class QScrollArea;
class QVBoxLayout;

namespace rs::ui {

class PageTitle;
class ProjectDocument;

// The I/O Options page (manual Part 1, 3.7 and 6): every terminal of the
// unit's type with its type of signal, signal shape and option boxes. The
// lists hold only what the terminal can take given the choices to their left,
// and an option box is enabled only where the option applies, so no illegal
// combination can be entered. Each change is one undo step. A terminal bound
// to a pin of a block instance says so.
class IoOptionsPage : public QWidget {
    Q_OBJECT
public:
    explicit IoOptionsPage(QWidget* parent = nullptr);

    void showUnit(ProjectDocument* document, int station);

    static QString signalTypeName(project::SignalType type);
    static QString signalShapeName(project::SignalShape shape);

private:
    struct Row {
        project::Terminal terminal;
        QComboBox* type = nullptr;
        QComboBox* shape = nullptr;
        QCheckBox* nonInverted = nullptr;
        QCheckBox* noFilter = nullptr;
        QCheckBox* crossTalk = nullptr;
        QCheckBox* noTestPulse = nullptr;
        QLabel* instanceUses = nullptr; // the block pins bound to the terminal
    };

    void rebuild();
    void refresh();
    void fill(Row& row, const project::TerminalSetting& setting);
    void showInstanceUses();
    void apply(const Row& row);
    project::TerminalSetting settingOf(const Row& row) const;

    PageTitle* m_title;
    QScrollArea* m_scroll;
    QWidget* m_content = nullptr;
    std::vector<Row> m_rows;
    QPointer<ProjectDocument> m_document;
    int m_station = 0;
    int m_builtType = -1;
    bool m_filling = false;
};

} // namespace rs::ui
