// SPDX-License-Identifier: GPL-3.0-or-later
#include "pl110/Pl110Document.h"

#include "pl110/ProgramCheck.h"
#include "pl110/ProgramText.h"
#include "project/ProjectFile.h"

#include <QFileInfo>
#include <QUndoCommand>
#include <QUuid>

#include <utility>

namespace rs::ui {

namespace {

std::string_view view(const QByteArray& bytes) {
    return {bytes.constData(), static_cast<std::size_t>(bytes.size())};
}

} // namespace

// One replacement of the whole text. The texts are kept rather than diffs:
// a PL110 program is at most 1 MB and most are a few kilobytes.
class Pl110TextCommand : public QUndoCommand {
public:
    Pl110TextCommand(Pl110Document* document, QByteArray before, QByteArray after,
                     const QString& what, bool typed)
        : QUndoCommand(what), m_document(document), m_before(std::move(before)),
          m_after(std::move(after)), m_typed(typed) {}

    void undo() override { m_document->apply(m_before); }
    void redo() override { m_document->apply(m_after); }
    int id() const override { return m_typed ? kTypingId : -1; }
    bool mergeWith(const QUndoCommand* other) override {
        const auto* next = static_cast<const Pl110TextCommand*>(other);
        if (!next->m_typed)
            return false;
        m_after = next->m_after;
        return true;
    }

private:
    static constexpr int kTypingId = 0x110;
    Pl110Document* m_document;
    QByteArray m_before;
    QByteArray m_after;
    bool m_typed;
};

Pl110Document::Pl110Document(QObject* parent)
    : QObject(parent), m_autosaveId(QUuid::createUuid().toString(QUuid::WithoutBraces)) {
    connect(&m_undo, &QUndoStack::cleanChanged, this,
            [this] { Q_EMIT modifiedChanged(isModified()); });
}

Pl110Document* Pl110Document::open(const QString& path, QString& error, QObject* parent) {
    const project::FileText file = project::readTextFile(path);
    if (!file.error.isEmpty()) {
        error = file.error;
        return nullptr;
    }
    if (!pl110::isPl110Text(file.text)) {
        error = tr("It is not a PL110 program: its first line is not “$target PL110”.");
        return nullptr;
    }
    auto* document = new Pl110Document(parent);
    document->m_path = QFileInfo(path).absoluteFilePath();
    document->apply(QByteArray::fromStdString(file.text));
    return document;
}

Pl110Document* Pl110Document::create(const QString& name, QObject* parent) {
    auto* document = new Pl110Document(parent);
    document->m_name = name;
    // A start/stop circuit that runs as it stands, so a new program shows the
    // ladder and the simulator at once.
    const QString text = QStringLiteral("$target PL110\n"
                                        "$name %1\n"
                                        "! I1=Start\n"
                                        "! I2=Stop\n"
                                        "! Q1=Motor\n"
                                        "\n"
                                        "INIT\n"
                                        "MAIN\n"
                                        "Motor = Start * Stop + Motor * Stop\n")
                             .arg(name);
    document->apply(text.toUtf8());
    return document;
}

Pl110Document* Pl110Document::recover(const QByteArray& text, const QString& path,
                                      const QString& autosaveId, QObject* parent) {
    auto* document = new Pl110Document(parent);
    document->m_path = path;
    document->m_autosaveId = autosaveId;
    document->m_recovered = true;
    document->apply(text);
    return document;
}

QString Pl110Document::displayName() const {
    if (!m_path.isEmpty())
        return QFileInfo(m_path).fileName();
    return m_name.isEmpty() ? tr("Untitled") : m_name;
}

void Pl110Document::apply(const QByteArray& text) {
    m_text = text;
    pl110::ProgramReading reading = pl110::readProgram(view(text));
    m_program = std::move(reading.program);
    m_diagnostics = std::move(reading.diagnostics);
    m_readsWhole = lang::errorCount(m_diagnostics) == 0;
    if (m_readsWhole) {
        lang::Diagnostics checks = pl110::checkProgram(m_program);
        m_diagnostics.insert(m_diagnostics.end(), checks.begin(), checks.end());
    }
    lang::sortByPlace(m_diagnostics);
    Q_EMIT changed();
}

void Pl110Document::setText(const QByteArray& text, const QString& what, bool typed) {
    if (text == m_text)
        return;
    m_undo.push(new Pl110TextCommand(this, m_text, text, what, typed));
}

void Pl110Document::setProgram(const pl110::Program& program, const QString& what) {
    Q_ASSERT(m_readsWhole);
    setText(QByteArray::fromStdString(pl110::printProgram(program)), what);
}

void Pl110Document::saved() {
    const bool wasRecovered = std::exchange(m_recovered, false);
    m_undo.setClean();
    if (wasRecovered)
        Q_EMIT modifiedChanged(false);
}

QString Pl110Document::save() {
    if (m_path.isEmpty())
        return tr("The program has no file yet: use Save As.");
    const QString error = project::writeTextFile(m_path, view(m_text));
    if (error.isEmpty())
        saved();
    return error;
}

QString Pl110Document::saveAs(const QString& path) {
    const QString error = project::writeTextFile(path, view(m_text));
    if (!error.isEmpty())
        return error;
    m_path = QFileInfo(path).absoluteFilePath();
    saved();
    Q_EMIT pathChanged();
    return {};
}

} // namespace rs::ui
