// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#ifndef Q_MOC_RUN
#include "lang/Diagnostic.h"
#include "pl110/Program.h"
#endif

#include <QObject>
#include <QUndoStack>

namespace rs::ui {

// A PL110 program open in the window (docs/pl110.md). Its text is the single
// source of truth: the ladder, the names page and the simulation read the
// program the text reads as, and every change, typed or made on another
// page, is one undoable replacement of the text.
class Pl110Document : public QObject {
    Q_OBJECT
public:
    // The program of a file; nothing, with the reason, when it cannot be read
    // or is not a PL110 program.
    static Pl110Document* open(const QString& path, QString& error, QObject* parent = nullptr);
    // A new program with the given name, not yet saved anywhere.
    static Pl110Document* create(const QString& name, QObject* parent = nullptr);
    // An autosaved copy taken back after a crash: modified, with its file
    // (empty when it never had one) and its copy's id.
    static Pl110Document* recover(const QByteArray& text, const QString& path,
                                  const QString& autosaveId, QObject* parent = nullptr);

    QString path() const { return m_path; }
    QString displayName() const;
    QByteArray text() const { return m_text; }
    bool isModified() const { return m_recovered || !m_undo.isClean(); }
    // Names the document's autosaved copy (ui/document/Autosave).
    QString autosaveId() const { return m_autosaveId; }
    QUndoStack* undoStack() { return &m_undo; }

    // The program as the text reads: lines with reading errors are left out.
    const pl110::Program& program() const { return m_program; }
    // Reading errors, then the checks' (only for text that reads).
    const lang::Diagnostics& diagnostics() const { return m_diagnostics; }
    // Whether every line reads: only then may a page print the program in
    // place of the text, as printing leaves out what does not read.
    bool readsWhole() const { return m_readsWhole; }
    // Whether the simulator may run it: it reads and passes the checks.
    bool isRunnable() const { return lang::errorCount(m_diagnostics) == 0; }

    // Replaces the text as one undoable step. Typing merges: consecutive
    // typed changes undo together until another kind of change comes.
    void setText(const QByteArray& text, const QString& what, bool typed = false);
    // The program printed canonically in place of the text, as one step: how
    // the pages that change the program (names, CSV) apply it; only when the
    // text reads whole.
    void setProgram(const pl110::Program& program, const QString& what);

    // Writes the text; an empty string when it worked, else why not. The file
    // is replaced only when the whole text is written (QSaveFile).
    QString save();
    QString saveAs(const QString& path);

Q_SIGNALS:
    void changed();
    void pathChanged();
    void modifiedChanged(bool modified);

private:
    friend class Pl110TextCommand;
    explicit Pl110Document(QObject* parent);
    void apply(const QByteArray& text);
    void saved();

    QString m_path;
    QString m_name;
    QByteArray m_text;
    pl110::Program m_program;
    lang::Diagnostics m_diagnostics;
    bool m_readsWhole = true;
    QUndoStack m_undo;
    QString m_autosaveId;
    bool m_recovered = false; // modified until saved, whatever the undo stack says
};

} // namespace rs::ui
