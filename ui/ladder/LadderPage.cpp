// SPDX-License-Identifier: GPL-3.0-or-later
#include "LadderPage.h"

#include "DragTool.h"
#include "ElementIcon.h"
#include "IdleTool.h"
#include "LadderActions.h"
#include "LadderView.h"
#include "LiveTool.h"
#include "NetworkEditTool.h"
#include "NetworkItem.h"
#include "StepHeaderItem.h"
#include "document/PermissionNote.h"
#include "document/ProjectDocument.h"
#include "ladder/CursorNavigation.h"
#include "lang/Address.h"
#include "output/SettledCompile.h"
#include "shell/PageTitle.h"
#include "shell/UnitCaption.h"

#include <QAction>
#include <QActionGroup>
#include <QDrag>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QLabel>
#include <QMenu>
#include <QMimeData>
#include <QScrollBar>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>

namespace rs::ui {

LadderPage::LadderPage(QWidget* parent)
    : QWidget(parent), m_title(new PageTitle(this)), m_toolBar(new QToolBar(this)),
      m_networkBar(new QToolBar(this)), m_scene(new QGraphicsScene(this)),
      m_view(new LadderView(m_scene, this)), m_status(new QLabel(this)),
      m_actions(std::make_unique<LadderActions>(this)),
      m_idleTool(std::make_unique<IdleTool>(*this)),
      m_networkEditTool(std::make_unique<NetworkEditTool>(*this)),
      m_dragTool(std::make_unique<DragTool>(*this)), m_liveTool(std::make_unique<LiveTool>(*this)),
      m_tool(m_idleTool.get()) {
    setObjectName(QStringLiteral("ladderPage"));
    m_view->setObjectName(QStringLiteral("ladderView"));
    m_toolBar->setObjectName(QStringLiteral("ladderToolBar"));
    m_networkBar->setObjectName(QStringLiteral("ladderNetworkBar"));
    m_status->setObjectName(QStringLiteral("ladderStatus"));
    m_status->setWordWrap(true);
    m_drawing = drawingFor(palette());
    m_view->setBackgroundBrush(m_drawing.style.background);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addWidget(m_networkBar);
    layout->addWidget(m_toolBar);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_status);
    m_editingHint =
        tr("No networks yet. Press %1, or right-click > New Network, then insert the network's "
           "output (L coil, S set, R reset, J jump ...) and its contacts.")
            .arg(LadderActions::keyOf(m_actions->newNetwork));
    m_emptyHint = m_scene->addSimpleText(m_editingHint);
    m_emptyHint->setVisible(false);
    const std::pair<QToolBar*, std::vector<QAction*>> bars[] = {
        {m_networkBar, m_actions->networkBar()}, {m_toolBar, m_actions->elementBar()}};
    for (const auto& [bar, actions] : bars)
        for (QAction* action : actions) {
            if (action)
                bar->addAction(action);
            else
                bar->addSeparator();
        }
    m_toolBar->setIconSize(kElementIconSize);
    drawElementIcons();
    connectActions();
    m_view->setKeyActions(m_actions->viewKeys);
    connect(m_view, &LadderView::pressed, this,
            [this](const QPointF& at, Qt::MouseButton button, Qt::KeyboardModifiers modifiers) {
                m_tool->pressed(at, button, modifiers);
            });
    connect(m_view, &LadderView::doubleClicked, this,
            [this](const QPointF& at) { m_tool->doubleClicked(at); });
    connect(m_view, &LadderView::menuRequested, this,
            [this](const QPointF& at, const QPoint& global) { m_tool->menuRequested(at, global); });
    connect(m_view, &LadderView::dragStarted, this,
            [this](const QPointF& from) { m_tool->dragStarted(from); });
    connect(m_view, &LadderView::dragHovered, this, &LadderPage::showDropPlace);
    connect(m_view, &LadderView::dragLeft, this, &LadderPage::hideDropPlace);
    connect(m_view, &LadderView::dropped, this,
            [this](const QPointF& at, const QByteArray& payload, bool move) {
                m_tool->dropped(at, payload, move);
            });
    connect(m_view, &LadderView::cutRequested, this, &LadderPage::cutNetworks);
    connect(m_view, &LadderView::copyRequested, this, &LadderPage::copyNetworks);
    connect(m_view, &LadderView::pasteRequested, this, &LadderPage::pasteNetworks);
    setFocusProxy(m_view);
}

LadderPage::~LadderPage() = default;

QAction* LadderPage::action(const QString& objectName) const {
    return findChild<QAction*>(objectName);
}

void LadderPage::connectActions() {
    const LadderActions& a = *m_actions;
    auto on = [this](QAction* action, auto slot) {
        connect(action, &QAction::triggered, this, slot);
    };
    on(a.showText, [this] { emit textRequested(); });
    on(a.placeAfter, [this] { setPlacement(Placement::After); });
    on(a.placeBefore, [this] { setPlacement(Placement::Before); });
    on(a.placeParallel, [this] { setPlacement(Placement::Parallel); });
    for (const auto& [kind, action] : a.insert)
        on(action, [this, kind = kind] { insertElement(kind); });
    on(a.deleteSelection, [this] { deleteSelection(); });
    on(a.newNetwork, [this] { newNetwork(); });
    on(a.insertBlock, [this] { insertBlock(); });
    on(a.updateBlock, [this] { updateBlock(); });
    on(a.makeBlock, [this] { makeBlock(); });
    on(a.blockDocumentation, [this] { showBlockDocumentation(); });
    on(a.expandAll, [this] { setAllCollapsed(false); });
    on(a.collapseAll, [this] { setAllCollapsed(true); });
    on(a.editNetwork, [this] { enterEditMode(); });
    on(a.updateNetwork, [this] { updateNetwork(); });
    on(a.undoNetwork, [this] { undoNetwork(); });
    on(a.zoomIn, [this] { m_view->zoomIn(); });
    on(a.zoomOut, [this] { m_view->zoomOut(); });
    on(a.zoomReset, [this] { m_view->setZoom(1); });
    on(a.print, [this] { print(); });
    on(a.exportPdf, [this] { exportPdf({}); });
    on(a.properties, [this] { m_tool->openProperties(); });
    on(a.toggle, [this] { m_tool->toggle(); });
    on(a.operandMenu, [this] { m_tool->openOperandMenu(); });
    on(a.moveLeft, [this] { moveCursor(ladder::CursorMove::Left); });
    on(a.moveRight, [this] { moveCursor(ladder::CursorMove::Right); });
    on(a.moveUp, [this] { moveCursor(ladder::CursorMove::Up); });
    on(a.moveDown, [this] { moveCursor(ladder::CursorMove::Down); });
    on(a.selectGroup, [this] { moveCursor(ladder::CursorMove::Out); });
    on(a.selectNetwork, [this] { moveCursor(ladder::CursorMove::Network); });
    on(a.newConfigOption, [this] { newConfigOption(); });
    on(a.cutNetworks, [this] { cutNetworks(); });
    on(a.copyNetworks, [this] { copyNetworks(); });
    on(a.pasteNetworks, [this] { pasteNetworks(); });
    on(a.deleteNetworks, [this] { deleteNetworks(); });
    on(a.networkComment, [this] { editNetworkComment(); });
    on(a.newStep, [this] { newStep(); });
    on(a.newSequence, [this] { emit newSequenceRequested(); });
}

void LadderPage::setPlacement(Placement placement) {
    m_placement = placement;
    QAction* checked[] = {m_actions->placeAfter, m_actions->placeBefore, m_actions->placeParallel};
    checked[static_cast<int>(placement)]->setChecked(true);
}

void LadderPage::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    if (event->type() != QEvent::PaletteChange)
        return;
    // The theme changed: the drawing follows the window's colours.
    applyColours();
}

void LadderPage::setColours(const LadderColours& colours) {
    m_colours = colours;
    applyColours();
}

void LadderPage::applyColours() {
    const LadderDrawing colours = drawingFor(palette(), m_colours, m_drawing.live != nullptr);
    m_drawing.style = colours.style;
    m_drawing.selection = colours.selection;
    m_drawing.markedNetwork = colours.markedNetwork;
    m_drawing.problem = colours.problem;
    m_drawing.editing = colours.editing;
    m_drawing.explained = colours.explained;
    m_view->setBackgroundBrush(m_drawing.style.background);
    drawElementIcons();
    repaintItems();
}

void LadderPage::drawElementIcons() {
    for (const auto& [kind, action] : m_actions->insert)
        action->setIcon(elementIcon(kind, m_drawing.style));
    m_actions->insertBlock->setIcon(blockIcon(m_drawing.style));
}

// ----- showing the model

void LadderPage::showUnit(ProjectDocument* document, int station, int sequence) {
    if (m_document != document) {
        if (m_document)
            disconnect(m_document, nullptr, this, nullptr);
        if (document) {
            connect(document, &ProjectDocument::changed, this, &LadderPage::followModel);
            connect(document, &ProjectDocument::pathChanged, this, &LadderPage::updateTitle);
            connect(document, &ProjectDocument::permissionChanged, this, &LadderPage::updateTitle);
        }
        if (m_compile)
            disconnect(m_compile, nullptr, this, nullptr);
        m_compile = document ? SettledCompile::of(document) : nullptr;
        if (m_compile) {
            // Without a baseline the page has nothing to mark: editing compiles nothing.
            m_compile->addViewer(
                this, [this] { return m_document && m_document->project().baseline.has_value(); });
            connect(m_compile, &SettledCompile::computed, this,
                    &LadderPage::showChangesSinceValidation);
        }
    }
    const bool samePage = document == m_document && station == m_station && sequence == m_sequence;
    m_document = document;
    m_station = station;
    m_sequence = sequence;
    if (!samePage) {
        m_pending.reset();
        endEditSession();
        m_drawing.cursor = {};
        m_drawing.marked.clear();
        m_drawing.problems.clear();
        for (auto& step : m_items)
            for (NetworkItem* item : step)
                delete item;
        m_items.clear();
        for (StepHeaderItem* header : m_headers)
            delete header;
        m_headers.clear();
    }
    rebuild();
    updateTitle();
    if (!samePage) {
        showChangesSinceValidation();
        if (stepCount() > 0 && networkCount(0) > 0)
            setCursor({0, 0, std::nullopt, std::nullopt, -1});
        // A page opens at its top left, whatever the view's size is yet.
        m_view->verticalScrollBar()->setValue(0);
        m_view->horizontalScrollBar()->setValue(0);
    }
}

void LadderPage::updateTitle() {
    if (!m_document) {
        m_title->setTitle({});
        return;
    }
    m_title->setTitle(pageTitle());
    // The keys that work now: simulating, the page is for watching and forcing.
    const LadderActions& a = *m_actions;
    auto keys = [](const QAction* action) {
        QStringList names;
        for (const QKeySequence& key : action->shortcuts())
            names << key.toString(QKeySequence::NativeText);
        return names.join(QLatin1Char('/'));
    };
    if (m_tool->forcesOperands()) {
        m_title->setSubtitle(
            tr("Simulating: a click or %1 on an input toggles it; a right click or %2 forces any "
               "element's variable. Editing ends the simulation.")
                .arg(keys(a.toggle), keys(a.operandMenu)));
        return;
    }
    // Password protected: the elements cannot be placed, so their bar goes.
    const project::Permission permission = m_document->permission();
    m_toolBar->setVisible(permission == project::Permission::Full);
    if (permission == project::Permission::ReadOnly) {
        m_title->setSubtitle(permissionNote(permission));
        return;
    }
    if (permission == project::Permission::Configure) {
        m_title->setSubtitle(tr("Password protected, open with permission to configure: a "
                                "click or %1 on a Config Option's box checks or unchecks it; "
                                "nothing else can change.")
                                 .arg(keys(a.toggle)));
        return;
    }
    QStringList inserts;
    for (const auto& [kind, action] : a.insert)
        inserts << LadderActions::keyOf(action);
    inserts << LadderActions::keyOf(a.insertBlock);
    m_title->setSubtitle(
        tr("Keys: %1 insert the toolbar's elements; %2 %3 %4 before, after, "
           "parallel; %5 properties; %6 delete; %7 new network; %8 edit mode.")
            .arg(inserts.join(QLatin1Char(' ')), LadderActions::keyOf(a.placeBefore),
                 LadderActions::keyOf(a.placeAfter), LadderActions::keyOf(a.placeParallel),
                 LadderActions::keyOf(a.properties), LadderActions::keyOf(a.deleteSelection),
                 LadderActions::keyOf(a.newNetwork), LadderActions::keyOf(a.editNetwork)));
}

QString LadderPage::pageTitle() const {
    if (!m_document)
        return {};
    const QString unit = unitCaption(m_document->project(), m_station);
    return m_sequence == 0 ? tr("%1 — PLC Code").arg(unit)
                           : tr("%1 — Sequence %2").arg(unit).arg(m_sequence);
}

void LadderPage::setMessage(const QString& message) {
    m_status->setText(message);
}

QString LadderPage::message() const {
    return m_status->text();
}

void LadderPage::updateActions() {
    // An undrawn page offers no edits: they would act on a ladder it does not hold.
    const bool drawn = m_undrawnLines == 0;
    const bool edits = editable() && drawn;
    m_view->setEnabled(drawn);
    // Viewing stays possible while simulating; only editing stops.
    const std::vector<QAction*> viewing = m_actions->viewing();
    for (QAction* action : findChildren<QAction*>(QString(), Qt::FindDirectChildrenOnly))
        if (std::find(viewing.begin(), viewing.end(), action) == viewing.end())
            action->setEnabled(edits);
    const bool watching = m_document && drawn && m_tool->forcesOperands();
    m_actions->toggle->setEnabled(edits || watching);
    m_actions->operandMenu->setEnabled(watching);
    m_actions->updateNetwork->setEnabled(edits && isEditingNetwork());
    m_actions->undoNetwork->setEnabled(edits && isEditingNetwork());
}

// ----- the state of the tools

void LadderPage::setTool(LadderTool& tool) {
    m_tool = &tool;
    if (const EditSession* session = tool.editSession())
        m_drawing.editingNetwork = std::make_pair(session->step, session->network);
    else
        m_drawing.editingNetwork.reset();
    updateActions();
}

LadderTool& LadderPage::restingTool() {
    if (m_drawing.live)
        return *m_liveTool;
    return *m_idleTool;
}

void LadderPage::rest() {
    setTool(restingTool());
}

void LadderPage::endEditSession() {
    m_tool->endEditSession();
    setTool(*m_tool);
}

const EditSession* LadderPage::editSession() const {
    return m_tool->editSession();
}

bool LadderPage::editable() const {
    return m_document && m_tool->edits();
}

// ----- live state

void LadderPage::setLiveState(const LadderLiveState* state) {
    const bool changedMode = (state == nullptr) != (m_drawing.live == nullptr);
    if (changedMode && state)
        undoNetwork();
    m_drawing.live = state;
    if (changedMode) {
        applyColours(); // lines off while simulating, lines while editing
        rest();
        updateTitle();
        placeItems();
    }
    explainOutput(); // each scan may change the answer
    repaintItems();
}

QColor LadderPage::elementColor(std::uint32_t statement, std::uint16_t element) const {
    if (m_drawing.live && m_drawing.live->power.conducts(statement, element))
        return m_drawing.style.powered;
    return m_drawing.style.ink;
}

// ----- selection

const ladder::ElementLayout* LadderPage::cursorElement() const {
    const LadderCursor& cursor = m_drawing.cursor;
    NetworkItem* item = networkItem(cursor.step, cursor.network);
    return item ? ladder::elementUnder(item->layout(), cursor) : nullptr;
}

void LadderPage::setCursor(const LadderCursor& cursor) {
    m_drawing.cursor = cursor;
    QString text;
    if (const ladder::ElementLayout* element = cursorElement()) {
        const auto found = m_drawing.problems.find({element->statement, element->element});
        if (found != m_drawing.problems.end())
            text = found->second;
        else if (element->output >= 0)
            if (const auto whole = m_drawing.problems.find({element->statement, 0});
                whole != m_drawing.problems.end())
                text = whole->second;
    }
    setMessage(text);
    if (m_drawing.live)
        explainOutput();
    ensureCursorVisible();
    repaintItems();
}

bool LadderPage::selectElement(std::uint32_t statement, std::uint16_t element) {
    for (std::size_t s = 0; s < m_items.size(); ++s)
        for (NetworkItem* item : m_items[s])
            for (const auto& e : item->layout().elements)
                if (e.statement == statement && e.element == element) {
                    setCursor(ladder::cursorOn(item->step(), item->index(), e));
                    return true;
                }
    return false;
}

bool LadderPage::selectOperand(const lang::Address& operand) {
    const auto has = [&operand](const ladder::ElementLayout& e) {
        const lang::AddressWord word = lang::readAddressWord(e.address.toStdString());
        return word.shape == lang::AddressWord::Shape::Variable && word.address == operand;
    };
    // Why an output is on or off is what the live page explains.
    for (const bool output : {true, false})
        for (std::size_t s = 0; s < m_items.size(); ++s)
            for (NetworkItem* item : m_items[s])
                for (const auto& e : item->layout().elements)
                    if ((e.output >= 0) == output && has(e)) {
                        setCursor(ladder::cursorOn(item->step(), item->index(), e));
                        return true;
                    }
    return false;
}

bool LadderPage::selectNetwork(const lang::StepAddress& step, int number) {
    for (int s = 0; s < stepCount(); ++s)
        if (m_steps[s].address == step && number >= 1 && number <= networkCount(s)) {
            setCursor({s, number - 1, std::nullopt, std::nullopt, -1});
            return true;
        }
    return false;
}

void LadderPage::ensureCursorVisible() {
    const LadderCursor& cursor = m_drawing.cursor;
    NetworkItem* item = networkItem(cursor.step, cursor.network);
    if (!item)
        return;
    QRectF rect = item->boundingRect();
    if (const ladder::ElementLayout* element = cursorElement())
        rect = item->elementRect(*element);
    else if (cursor.node)
        rect = item->groupRect(*cursor.node);
    // Of a network or group larger than the view, its top left is what
    // must show: ensureVisible would bring its bottom right into view.
    const QSizeF view = m_view->mapToScene(m_view->viewport()->rect()).boundingRect().size();
    rect.setWidth(std::min(rect.width(), std::max<qreal>(view.width() - 40, 1)));
    rect.setHeight(std::min(rect.height(), std::max<qreal>(view.height() - 40, 1)));
    m_view->ensureVisible(item->mapRectToScene(rect), 20, 20);
}

NetworkItem* LadderPage::itemAt(const QPointF& scenePosition) const {
    for (const auto& step : m_items)
        for (NetworkItem* item : step)
            if (item->sceneBoundingRect().contains(scenePosition))
                return item;
    return nullptr;
}

LadderCursor LadderPage::cursorAt(const QPointF& scenePosition) const {
    NetworkItem* item = itemAt(scenePosition);
    if (!item)
        return {};
    const int index = item->elementAt(item->mapFromScene(scenePosition));
    if (index < 0)
        return {item->step(), item->index(), std::nullopt, std::nullopt, -1};
    return ladder::cursorOn(item->step(), item->index(), item->layout().elements[index]);
}

void LadderPage::moveCursor(ladder::CursorMove move) {
    ladder::LaidOutPage page;
    for (const auto& step : m_items) {
        page.emplace_back();
        for (NetworkItem* item : step)
            page.back().push_back({&item->layout(), item->collapsed()});
    }
    if (const auto moved = ladder::movedCursor(page, m_drawing.cursor, move))
        setCursor(*moved);
}

} // namespace rs::ui
