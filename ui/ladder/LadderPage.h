// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ElementKind.h"
#include "LadderDrawing.h"
#include "LadderLiveState.h"
#ifndef Q_MOC_RUN
#include "ladder/UnitLadder.h"
#include "lang/Diagnostic.h"
#endif

#include <QColor>
#include <QPointer>
#include <QWidget>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <vector>

class QAction;
class QActionGroup;
class QGraphicsScene;
class QGraphicsSimpleTextItem;
class QKeyEvent;
class QLabel;
class QPagedPaintDevice;
class QToolBar;

namespace rs::ui {

class LadderView;
class NetworkItem;
class PageTitle;
class ProjectDocument;
class StepHeaderItem;

// The ladder view of a unit's PLC code (sequence 0) or of one of its
// sequences (manual Part 1, 11): numbered networks with their comments, one
// scene item per network. Every edit is one undo step of the project, made
// through the ladder model's editing operations, so every drawing is a
// program; the text page shows it at once, and a change of the text lays the
// ladder out again. In a network's edit mode (manual 11.1, 11.3) edits gather
// in the network until Update (F3) makes them one undo step or Undo (F2)
// drops them.
class LadderPage : public QWidget {
    Q_OBJECT
public:
    // Where the next element goes relative to what is selected.
    enum class Placement { After, Before, Parallel };

    explicit LadderPage(QWidget* parent = nullptr);
    ~LadderPage() override;

    void showUnit(ProjectDocument* document, int station, int sequence);
    ProjectDocument* document() const { return m_document; }
    int station() const { return m_station; }
    int sequence() const { return m_sequence; }

    // The simulator's state; nullptr for editing. Calling again with the same
    // pointer repaints without laying anything out.
    void setLiveState(const LadderLiveState* state);
    bool isLive() const { return m_drawing.live != nullptr; }
    // The colour the element is drawn with now: powered, or not.
    QColor elementColor(std::uint32_t statement, std::uint16_t element) const;

    // Diagnostics of the unit's text (lines and columns of its code as the
    // text page shows it), drawn on the elements they concern.
    void setDiagnostics(const lang::Diagnostics& diagnostics);
    const std::map<std::pair<std::uint32_t, std::uint16_t>, QString>& problems() const {
        return m_drawing.problems;
    }

    LadderView* view() const { return m_view; }
    QGraphicsScene* scene() const { return m_scene; }
    int stepCount() const { return static_cast<int>(m_steps.size()); }
    int networkCount(int step) const;
    NetworkItem* networkItem(int step, int network) const;
    const LadderCursor& cursor() const { return m_drawing.cursor; }
    void setCursor(const LadderCursor& cursor);
    // Selects the element or output drawn with this number (statement, element).
    bool selectElement(std::uint32_t statement, std::uint16_t element);
    // Why the last edit was refused, or what the page has to say.
    QString message() const;
    Placement placement() const { return m_placement; }
    void setPlacement(Placement placement);
    QAction* action(const QString& objectName) const;

    // Opens the properties dialog for a new element of the kind and inserts it.
    void insertElement(ElementKind kind);
    void editProperties();
    void deleteSelection();
    // Moves an element or group next to another, within a network, between
    // networks or between steps (what dragging does). False when refused.
    bool moveElement(const LadderCursor& from, const LadderCursor& to, ladder::Side side);
    void newNetwork();
    // A Config Option network at the start of the PLC code (manual 11.6).
    void newConfigOption();
    void editConfigOption(int step, int network);
    void toggleConfigOption(int step, int network);
    void copyNetworks();
    void cutNetworks();
    void pasteNetworks();
    void deleteNetworks();
    void setAllCollapsed(bool collapsed);
    void toggleCollapsed(int step, int network);
    void editNetworkComment();
    void newStep();
    void editStepComment(int step);
    bool isEditingNetwork() const { return m_editSession.has_value(); }
    void enterEditMode();
    void updateNetwork(); // F3
    void undoNetwork();   // F2
    // Draws every network of the page on pages of the device, scaled to its width.
    void paintPages(QPagedPaintDevice& device, const QString& title) const;
    bool exportPdf(const QString& path);
    void print();

protected:
    void changeEvent(QEvent* event) override;

signals:
    // The user asked for the text of this code (the "Text" button).
    void textRequested();
    void newSequenceRequested();
    // While live: a click on an element with an operand, and a right click.
    void operandClicked(const QString& address);
    void operandMenuRequested(const QString& address, const QPoint& globalPos);

private:
    struct EditSession {
        int step = 0;
        int network = 0;
    };

    void createActions();
    // The insert buttons show the symbols in the theme's colours.
    void drawElementIcons();
    void followModel();
    void rebuild();
    void placeItems();
    void updateTitle();
    QString pageTitle() const;
    void updateActions();
    void setMessage(const QString& message);
    void repaintItems();

    bool handleLiveKey(int key, Qt::KeyboardModifiers modifiers);
    bool handleKey(QKeyEvent* event);
    void pressed(const QPointF& scenePosition, Qt::MouseButton button,
                 Qt::KeyboardModifiers modifiers);
    void doubleClicked(const QPointF& scenePosition);
    void showMenu(const QPointF& scenePosition, const QPoint& globalPosition);
    void startDrag(const QPointF& from);
    void drop(const QPointF& scenePosition, const QByteArray& payload);

    NetworkItem* itemAt(const QPointF& scenePosition) const;
    LadderCursor cursorAt(const QPointF& scenePosition) const;
    const ladder::ElementLayout* cursorElement() const;
    void moveCursor(int key);
    void ensureCursorVisible();
    std::vector<std::pair<int, int>> chosenNetworks() const;

    // Applies an edit to one network: in edit mode to the page's copy, else
    // as one undo step. Selects what the edit added. False when refused.
    bool editNetwork(const QString& name, int step, int network,
                     const std::function<ladder::EditResult(ladder::Network&)>& edit);
    void commitStep(const QString& name, int step, ladder::StepLadder ladder);
    // Several steps changed by one edit, as one undo step.
    void commitSteps(const QString& name, std::vector<std::pair<int, ladder::StepLadder>> steps);
    void selectAdded(int step, int network, const std::vector<QString>& before);

    PageTitle* m_title;
    QToolBar* m_toolBar;
    QGraphicsScene* m_scene;
    LadderView* m_view;
    QLabel* m_status;
    QString m_editingHint; // what an empty page says while editing
    QGraphicsSimpleTextItem* m_emptyHint = nullptr;
    QActionGroup* m_placementGroup = nullptr;
    QPointer<ProjectDocument> m_document;
    int m_station = 0;
    int m_sequence = 0;
    LadderDrawing m_drawing;
    std::vector<ladder::StepPage> m_steps;
    std::vector<QString> m_stepComments; // the trailing comment of each step's header
    std::vector<StepHeaderItem*> m_headers;
    std::vector<std::vector<NetworkItem*>> m_items;
    ladder::SymbolTable m_symbols;
    std::vector<lang::Line> m_names; // the declarations the symbols were read from
    int m_namesVersion = 0;
    std::size_t m_undrawnLines = 0;               // the code's lines when above what the page draws
    std::optional<std::pair<int, int>> m_pending; // a new network not yet holding a rung
    std::optional<EditSession> m_editSession;
    Placement m_placement = Placement::After;
};

} // namespace rs::ui
