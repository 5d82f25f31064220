// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ElementKind.h"
#include "LadderDrawing.h"
#include "LadderLiveState.h"
#ifndef Q_MOC_RUN
#include "blocks/InstanceStanding.h"
#include "ladder/Layout.h"
#include "ladder/UnitLadder.h"
#include "lang/Diagnostic.h"
#endif

#include <QColor>
#include <QPoint>
#include <QPointer>
#include <QWidget>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <vector>

class QAction;
class QGraphicsRectItem;
class QGraphicsScene;
class QGraphicsSimpleTextItem;
class QLabel;
class QMimeData;
class QPagedPaintDevice;
class QToolBar;

namespace rs::ladder {
enum class CursorMove;
} // namespace rs::ladder

namespace rs::ui {

class DragTool;
class IdleTool;
class LadderActions;
class LadderTool;
class LadderView;
class LiveTool;
class NetworkEditTool;
class NetworkItem;
class PageTitle;
class ProjectDocument;
class SettledCompile;
class StepHeaderItem;
struct EditSession;

// The ladder view of a unit's PLC code (sequence 0) or of one of its
// sequences (manual Part 1, 11): numbered networks with their comments, one
// scene item per network. Every edit is one undo step of the project, made
// through the ladder model's editing operations, so every drawing is a
// program; the text page shows it at once, and a change of the text lays the
// ladder out again. In a network's edit mode (manual 11.1, 11.3) edits gather
// in the network until Update (F3) makes them one undo step or Undo (F2)
// drops them.
//
// The page's definition is in files by idea: LadderPage.cpp (actions,
// titles, live state, selection), LadderPageScene.cpp (following the model),
// LadderPageInput.cpp (what the tool states do with the mouse and keys),
// LadderEditing.cpp, BlockNetworks.cpp, NetworkClipboard.cpp, LadderPrinting.cpp and
// LadderDiagnostics.cpp. The states themselves are IdleTool,
// NetworkEditTool, DragTool and LiveTool; the keys are LadderActions.
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
    // The user's colours (Preferences), applied at once; invalid ones follow the theme.
    void setColours(const LadderColours& colours);
    bool isLive() const { return m_drawing.live != nullptr; }
    const LadderLiveState* liveState() const { return m_drawing.live; }
    // What every network is drawn with: colours, live state, selection, marks.
    const LadderDrawing& drawing() const { return m_drawing; }
    // The variables bound to the pins of the page's block networks, whose
    // values the live state is to carry (render::PowerSnapshot::values).
    std::set<lang::Address> pinVariables() const;
    // The colour the element is drawn with now: powered, or not.
    QColor elementColor(std::uint32_t statement, std::uint16_t element) const;
    // While live with an output selected: why it is on or off, as the page's
    // status line says it ("Q0.2 is off: I0.13 is open, M0.0 is open"), and
    // the elements marked for it (the first that blocks each path of its
    // rung, or the path that holds it). Empty when no output is selected.
    QString outputExplanation() const { return m_explanation; }
    const std::set<std::pair<std::uint32_t, std::uint16_t>>& blockingElements() const {
        return m_drawing.blocking;
    }
    const std::set<std::pair<std::uint32_t, std::uint16_t>>& holdingElements() const {
        return m_drawing.holding;
    }

    // Diagnostics of the unit's text (lines and columns of its code as the
    // text page shows it), drawn on the elements they concern.
    void setDiagnostics(const lang::Diagnostics& diagnostics);
    const std::map<std::pair<std::uint32_t, std::uint16_t>, QString>& problems() const {
        return m_drawing.problems;
    }
    // The networks that differ from the validated baseline, by (step,
    // network), true when added; a bar left of each shows it.
    const std::map<std::pair<int, int>, bool>& changedSinceValidation() const {
        return m_drawing.sinceValidation;
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
    // Selects the output that writes the operand, else the first element that
    // reads it; false when no element of the page has it.
    bool selectOperand(const lang::Address& operand);
    // Selects a whole network of a step of the page, numbered from 1.
    bool selectNetwork(const lang::StepAddress& step, int number);
    // Why the last edit was refused, or what the page has to say.
    QString message() const;
    Placement placement() const { return m_placement; }
    void setPlacement(Placement placement);
    QAction* action(const QString& objectName) const;

    // Opens the properties dialog for a new element of the kind and inserts it.
    void insertElement(ElementKind kind);
    void editProperties();
    void deleteSelection();
    // Moves, or copies, an element or group next to another, within a
    // network, between networks or between steps (what dragging does). False
    // when refused.
    bool moveElement(const LadderCursor& from, const LadderCursor& to, ladder::Side side);
    bool copyElement(const LadderCursor& from, const LadderCursor& to, ladder::Side side);
    // What dragging the element at `from` carries; null where there is none.
    QMimeData* elementDragData(const QPointF& from) const;
    // A drag over the page: where its drop would put the element, drawn.
    void showDropPlace(const QPointF& scenePosition, const QByteArray& payload, bool move);
    void hideDropPlace();
    bool isDropPlaceShown() const;
    void dropElement(const QPointF& scenePosition, const QByteArray& payload, bool move);
    void newNetwork();
    // Inserts a network holding an instance of a library block (New Network →
    // Function…): the block chosen from the project's libraries, then its pins.
    void insertBlock();
    // The pins dialog of a block network.
    void editBlockPins(int step, int network);
    // Expands the selected instance again with its block's current version.
    void updateBlock();
    // Make Block…: the chosen networks become a block of a user library in
    // the project's folder, and an instance of it takes their place.
    void makeBlock();
    // The documentation page of the block the cursor's network holds.
    void showBlockDocumentation();
    // How the instance a block network holds stands; null for another network.
    const blocks::InstanceStatus* blockStatus(int step, int network) const;
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
    bool isEditingNetwork() const { return editSession() != nullptr; }
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
    void applyColours();
    static constexpr qreal kNetworkGap = 4; // between the networks, on screen and on paper

    // The states of the page's tools hand what the user does to the page.
    friend class DragTool;
    friend class IdleTool;
    friend class LiveTool;
    friend class NetworkEditTool;

    void connectActions();
    // The insert buttons show the symbols in the theme's colours.
    void drawElementIcons();
    void followModel();
    // Marks the networks the document's SettledCompile found changed since validation.
    void showChangesSinceValidation();
    void rebuild();
    // Follows an undo step that replaced a run of one step's lines by reading
    // and laying out only the networks the run touches; false where only
    // rebuild() can (block instances, a new network pending, a page too long).
    bool followStepLines();
    ladder::LayoutContext layoutContext(int step, int network) const;
    // Gives a network its item, laid out unless it is laid out already.
    void showNetwork(int step, int network);
    // A network whose item is laid out already, numbered where it is now.
    void renumberNetwork(int step, int network);
    // After items changed: placed, the cursor kept where it can be, repainted.
    void settleItems();
    void placeItems();
    void updateTitle();
    QString pageTitle() const;
    void updateActions();
    void setMessage(const QString& message);
    void repaintItems();

    // The state of the tools: events of the view go to it.
    void setTool(LadderTool& tool);
    LadderTool& restingTool();
    void rest();
    const EditSession* editSession() const;
    // Leaves the network's edit mode without keeping or dropping anything.
    void endEditSession();
    // Whether the page can edit now: a project, a drawn page, a state that edits.
    bool editable() const;

    // What the states do with the mouse and keys.
    bool toggleCollapseAt(const QPointF& scenePosition);
    bool toggleOptionAt(const QPointF& scenePosition);
    void select(const QPointF& scenePosition, Qt::MouseButton button,
                Qt::KeyboardModifiers modifiers);
    void openAt(const QPointF& scenePosition);
    void openSelected();
    void showEditMenu(const QPoint& globalPosition);
    void dragFrom(const QPointF& from, LadderTool& resume);
    void dragElement(const QPointF& from);
    // Where a drop of the payload at the position would put its element, and
    // the mark drawn there while dragging.
    struct DropPlace {
        LadderCursor from;
        LadderCursor to;
        ladder::Side side;
        QRectF mark;
    };
    std::optional<DropPlace> dropPlaceAt(const QPointF& scenePosition,
                                         const QByteArray& payload) const;
    enum class Transfer { Move, Copy };
    bool transferElement(const LadderCursor& from, const LadderCursor& to, ladder::Side side,
                         Transfer transfer);
    void pointAt(const QPointF& scenePosition);
    // Explains the selected output from the live state (outputExplanation()).
    void explainOutput();
    void reportOperand();
    void reportOperandMenu(std::optional<QPoint> globalPosition = std::nullopt);

    NetworkItem* itemAt(const QPointF& scenePosition) const;
    LadderCursor cursorAt(const QPointF& scenePosition) const;
    const ladder::ElementLayout* cursorElement() const;
    void moveCursor(ladder::CursorMove move);
    void ensureCursorVisible();
    std::vector<std::pair<int, int>> chosenNetworks() const;

    // Applies an edit to one network: in edit mode to the page's copy, else
    // as one undo step. Selects what the edit added. False when refused.
    bool editNetwork(const QString& name, int step, int network,
                     const std::function<ladder::EditResult(ladder::Network&)>& edit);
    void commitStep(const QString& name, int step, ladder::StepLadder ladder);
    // Networks [first, first + removed) of a step replaced by `added`, as one
    // undo step: only their lines are written where the step's other
    // networks keep theirs (ladder::networkRunLines), else the whole step.
    void commitNetworks(const QString& name, int step, int first, int removed,
                        std::vector<ladder::Network> added);
    // The index in the unit's steps of the page's step; nothing for a step
    // the project does not hold yet.
    std::optional<std::size_t> unitStepIndex(int step) const;
    // Several steps changed by one edit, as one undo step.
    void commitSteps(const QString& name, std::vector<std::pair<int, ladder::StepLadder>> steps);
    void selectAdded(int step, int network, const std::vector<QString>& before);
    // Writes a block network's instance anew, without statements, so that
    // committing expands it.
    void rewriteBlock(const QString& name, int step, int network, blocks::BlockInstance instance);
    // What a block network says under its box: that its block changed.
    QString blockNote(const blocks::InstanceStatus& status) const;

    PageTitle* m_title;
    QToolBar* m_toolBar;    // the elements
    QToolBar* m_networkBar; // the network and view commands
    QGraphicsScene* m_scene;
    LadderView* m_view;
    QLabel* m_status;
    QString m_explanation;
    QString m_editingHint; // what an empty page says while editing
    QGraphicsSimpleTextItem* m_emptyHint = nullptr;
    QGraphicsRectItem* m_dropPlace = nullptr; // where a dragged element would go
    QPointer<ProjectDocument> m_document;
    QPointer<SettledCompile> m_compile;
    int m_station = 0;
    int m_sequence = 0;
    LadderDrawing m_drawing;
    LadderColours m_colours;
    std::vector<ladder::StepPage> m_steps;
    std::vector<QString> m_stepComments; // the trailing comment of each step's header
    std::vector<StepHeaderItem*> m_headers;
    std::vector<std::vector<NetworkItem*>> m_items;
    std::vector<blocks::InstanceStatus> m_blockStatuses; // of the unit's instances
    ladder::SymbolTable m_symbols;
    std::vector<lang::Line> m_names; // the declarations the symbols were read from
    int m_namesVersion = 0;
    std::size_t m_undrawnLines = 0;               // the code's lines when above what the page draws
    std::optional<std::pair<int, int>> m_pending; // a new network not yet holding a rung
    bool m_pendingShown = false;                  // m_steps holds it, which the project does not
    Placement m_placement = Placement::After;
    std::unique_ptr<LadderActions> m_actions;
    std::unique_ptr<IdleTool> m_idleTool;
    std::unique_ptr<NetworkEditTool> m_networkEditTool;
    std::unique_ptr<DragTool> m_dragTool;
    std::unique_ptr<LiveTool> m_liveTool;
    LadderTool* m_tool = nullptr;
};

} // namespace rs::ui
