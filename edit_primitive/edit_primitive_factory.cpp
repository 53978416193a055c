#include "edit_primitive_factory.h"

#include "edit_primitive.h"

EditPrimitiveFactory::EditPrimitiveFactory()
{
  edit_ = new QAction(QIcon(":/edit_primitive/images/edit_primitive.png"), "Primitive Edit", this);
  edit_->setToolTip("Primitive Edit: pick, merge and split segments, fit primitives, edit their parameters and "
                    "snap segments onto them (Ctrl+Shift+P)");
  // A shortcut makes the tool reachable without finding its toolbar button (and scriptable in GUI tests).
  edit_->setShortcut(QKeySequence(Qt::CTRL + Qt::SHIFT + Qt::Key_P));
  edit_->setCheckable(true);
}

QList<QAction*> EditPrimitiveFactory::actions() const { return {edit_}; }

MeshEditInterface* EditPrimitiveFactory::getMeshEditInterface(QAction* action)
{
  return action == edit_ ? new EditPrimitivePlugin() : nullptr;
}

QString EditPrimitiveFactory::getEditToolDescription(QAction*) { return EditPrimitivePlugin::Info(); }

MESHLAB_PLUGIN_NAME_EXPORTER(EditPrimitiveFactory)
