// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#ifndef Q_MOC_RUN
#include "lang/Diagnostic.h"
#include "pl110/Program.h"
#endif

#include <QMainWindow>
#include <QTimer>

#include <cstdint>
#include <functional>
#include <string>

class QAction;
class QListWidget;
class QPlainTextEdit;
class QTabWidget;

namespace rs::ui {

class Pl110Document;
class Pl110LadderView;
class Pl110NamesPage;
class Pl110Simulation;
class Pl110WaveformPanel;
class ProgramEditor;

// The window of one PL110 program (docs/pl110.md, "The window"): its ladder,
// its text and its names as pages of one document with one undo history,
// the problems the reader and the checks find, and the simulator with live
// colouring, inputs set and variables forced from the ladder, and scenarios.
class Pl110Window : public QMainWindow {
    Q_OBJECT
public:
    enum class Page { Ladder, Program, Names };

    // Takes the document.
    explicit Pl110Window(Pl110Document* document, QWidget* parent = nullptr);
    // Lets go of the autosaved copy's lock, leaving the copy for recovery
    // when the window goes without being closed.
    ~Pl110Window() override;

    // Opens a program in a window of its own, shown; an empty string, or why
    // it could not be opened.
    static QString openWindow(const QString& path);
    // A new program in a window of its own, shown.
    static Pl110Window* newWindow(const QString& name);

    Pl110Document* document() const { return m_document; }
    Pl110Simulation* simulation() const { return m_simulation; }
    void showPage(Page page);
    // Scrolls the ladder to rung `number`; false when there is none.
    bool showRung(int number);
    // Runs a scenario file to its end and shows its results and the state it
    // ended in; an empty string, or why it did not run.
    QString runScenario(const QString& path);
    // Takes what was typed into the document now rather than after the pause.
    void applyTyping();
    // Writes the autosaved copy of a modified program now (the timer does it
    // every few minutes, as the preferences say).
    void autosaveNow();

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    enum class Insertion { Before, After, Parallel };
    void createActions();
    void createLadderActions(
        const std::function<QAction*(const QString&, const char*, const QKeySequence&)>& action);
    // The ladder's edits: each reads what the user typed, changes the
    // program in the core and replaces the text as one undoable step.
    bool mayEditLadder();
    void applyLadderEdit(const QString& what, const std::string& refusal,
                         const pl110::Program& edited, int select, std::uint16_t element = 0);
    static QString readProblem(const lang::Diagnostics& diagnostics);
    void newRung(bool intoInit);
    void editSelected();
    void insertAtSelection(Insertion where);
    void deleteSelected();
    void moveSelectedRung(int direction);
    void followDocument();
    void updateTitle();
    void updateSimulationActions();
    void refreshLive();
    void scheduleLiveRefresh();
    void operandClicked(const QString& address);
    void operandMenu(const QString& address, const QPoint& where);
    void goToLine(int line, int column = 1);
    bool save();
    bool saveAs();
    bool maySaveOrDiscard();
    void chooseScenario();
    void openOther();
    void simulationAnswer(const QString& error);

    Pl110Document* m_document;
    Pl110Simulation* m_simulation;
    QTabWidget* m_pages;
    Pl110LadderView* m_ladder;
    ProgramEditor* m_editor;
    Pl110NamesPage* m_names;
    QListWidget* m_problems;
    QPlainTextEdit* m_scenarioOutput;
    Pl110WaveformPanel* m_waveform;
    QTimer m_typing;
    QTimer m_liveRefresh;
    QTimer m_autosave;
    bool m_settingEditor = false;

    QAction* m_start = nullptr;
    QAction* m_stop = nullptr;
    QAction* m_singleScan = nullptr;
    QAction* m_reset = nullptr;
    QList<QAction*> m_ladderEdits;
};

} // namespace rs::ui
