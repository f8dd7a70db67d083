<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
<context>
    <name>CreaseConditionCommand</name>
    <message numerus="yes">
        <location filename="../model/document/commands/crease_condition_command.cpp" line="55"/>
        <source>Clear the condition of %n creases</source>
        <translation>
            <numerusform>Clear the condition of %n crease</numerusform>
            <numerusform>Clear the condition of %n creases</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/crease_condition_command.cpp" line="56"/>
        <source>%1 on %n creases</source>
        <translation>
            <numerusform>%1 on %n crease</numerusform>
            <numerusform>%1 on %n creases</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>MoveVerticesCommand</name>
    <message numerus="yes">
        <location filename="../model/document/commands/move_vertices_command.cpp" line="23"/>
        <source>Move %n vertices</source>
        <translation>
            <numerusform>Move %n vertex</numerusform>
            <numerusform>Move %n vertices</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/move_vertices_command.cpp" line="38"/>
        <source>Rotate %n vertices</source>
        <translation>
            <numerusform>Rotate %n vertex</numerusform>
            <numerusform>Rotate %n vertices</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>PinVerticesCommand</name>
    <message numerus="yes">
        <location filename="../model/document/commands/pin_vertices_command.cpp" line="29"/>
        <source>Pin %n vertices</source>
        <translation>
            <numerusform>Pin %n vertex</numerusform>
            <numerusform>Pin %n vertices</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/pin_vertices_command.cpp" line="29"/>
        <source>Unpin %n vertices</source>
        <translation>
            <numerusform>Unpin %n vertex</numerusform>
            <numerusform>Unpin %n vertices</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ProblemText</name>
    <message numerus="yes">
        <location filename="../app/text/problem_text.cpp" line="289"/>
        <source>The surface is not one sheet: it has %n separate part(s).</source>
        <translation>
            <numerusform>The surface is not one sheet: it has %n separate part.</numerusform>
            <numerusform>The surface is not one sheet: it has %n separate parts.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>RelabelEdgeCommand</name>
    <message numerus="yes">
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="28"/>
        <source>Relabel %n edges</source>
        <translation>
            <numerusform>Relabel %n edge</numerusform>
            <numerusform>Relabel %n edges</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SmoothRulingsCommand</name>
    <message numerus="yes">
        <location filename="../model/document/commands/smooth_rulings_command.cpp" line="39"/>
        <source>Make %n rulings smooth</source>
        <translation>
            <numerusform>Make %n ruling smooth</numerusform>
            <numerusform>Make %n rulings smooth</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/smooth_rulings_command.cpp" line="40"/>
        <source>Make %n rulings sharp</source>
        <translation>
            <numerusform>Make %n ruling sharp</numerusform>
            <numerusform>Make %n rulings sharp</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::ApproximateDialog</name>
    <message numerus="yes">
        <location filename="../app/gui/approximate_dialog.cpp" line="36"/>
        <source>%1 (%n point(s))</source>
        <translation>
            <numerusform>%1 (%n point)</numerusform>
            <numerusform>%1 (%n points)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::ApproximateReaction</name>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="168"/>
        <source>Thinning the reference shape with radius %1 kept %n point(s), too few for the strips asked for; choose a smaller radius or fewer strips.</source>
        <translation>
            <numerusform>Thinning the reference shape with radius %1 kept %n point, too few for the strips asked for; choose a smaller radius or fewer strips.</numerusform>
            <numerusform>Thinning the reference shape with radius %1 kept %n points, too few for the strips asked for; choose a smaller radius or fewer strips.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="285"/>
        <source>the reference shape is %1 from the %n surface(s) on average, %2 at most</source>
        <translation>
            <numerusform>the reference shape is %1 from the surface on average, %2 at most</numerusform>
            <numerusform>the reference shape is %1 from the %n surfaces on average, %2 at most</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="292"/>
        <source>Approximated with %n surface(s): %1.</source>
        <translation>
            <numerusform>Approximated with %n surface: %1.</numerusform>
            <numerusform>Approximated with %n surfaces: %1.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="295"/>
        <source>%n surface(s) too far from the shape were left as they were.</source>
        <translation>
            <numerusform>%n surface too far from the shape was left as it was.</numerusform>
            <numerusform>%n surfaces too far from the shape were left as they were.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="290"/>
        <source>The reference shape closes around an axis: its %n strip(s) were laid as rings one after another around it, one surface open only at its two ends.</source>
        <translation>
            <numerusform>The reference shape closes around an axis: its %n strip was laid as a ring around it, one surface open only at its two ends.</numerusform>
            <numerusform>The reference shape closes around an axis: its %n strips were laid as rings one after another around it, one surface open only at its two ends.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="290"/>
        <source>The reference shape is one patch: its %n strip(s) were laid side by side as one watertight surface.</source>
        <translation>
            <numerusform>The reference shape is one patch: its %n strip was laid as one watertight surface.</numerusform>
            <numerusform>The reference shape is one patch: its %n strips were laid side by side as one watertight surface.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="290"/>
        <source>%n strip(s) were trimmed back where they stood off the shape.</source>
        <translation>
            <numerusform>%n strip was trimmed back where it stood off the shape.</numerusform>
            <numerusform>%n strips were trimmed back where they stood off the shape.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="290"/>
        <source>%n strip(s) could not be pulled closer and stay developable; they were kept as they were laid.</source>
        <translation>
            <numerusform>%n strip could not be pulled closer and stay developable; it was kept as it was laid.</numerusform>
            <numerusform>%n strips could not be pulled closer and stay developable; they were kept as they were laid.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::DistanceReportDialog</name>
    <message numerus="yes">
        <location filename="../app/gui/distance_report_dialog.cpp" line="193"/>
        <source>Coverage: %1 of the %n point(s) lie within %2 of the design.</source>
        <translation>
            <numerusform>Coverage: %1 of the %n point lies within %2 of the design.</numerusform>
            <numerusform>Coverage: %1 of the %n points lie within %2 of the design.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::DragTool</name>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_sheet.cpp" line="148"/>
        <source>Drag %n vertices in the sheet</source>
        <translation>
            <numerusform>Drag %n vertex in the sheet</numerusform>
            <numerusform>Drag %n vertices in the sheet</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_text.cpp" line="16"/>
        <source>Drag %n vertices</source>
        <translation>
            <numerusform>Drag %n vertex</numerusform>
            <numerusform>Drag %n vertices</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_sheet.cpp" line="155"/>
        <source>Dragging %n vertices %1 mm along their sheet; the surface follows. Release to finish, Esc cancels.</source>
        <translation>
            <numerusform>Dragging %n vertex %1 mm along its sheet; the surface follows. Release to finish, Esc cancels.</numerusform>
            <numerusform>Dragging %n vertices %1 mm along their sheet; the surface follows. Release to finish, Esc cancels.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_text.cpp" line="73"/>
        <source>Dragging %n vertices %1 mm along X. Release to finish, Esc cancels.</source>
        <translation>
            <numerusform>Dragging %n vertex %1 mm along X. Release to finish, Esc cancels.</numerusform>
            <numerusform>Dragging %n vertices %1 mm along X. Release to finish, Esc cancels.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_text.cpp" line="76"/>
        <source>Dragging %n vertices %1 mm along Y. Release to finish, Esc cancels.</source>
        <translation>
            <numerusform>Dragging %n vertex %1 mm along Y. Release to finish, Esc cancels.</numerusform>
            <numerusform>Dragging %n vertices %1 mm along Y. Release to finish, Esc cancels.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_text.cpp" line="79"/>
        <source>Dragging %n vertices %1 mm along Z. Release to finish, Esc cancels.</source>
        <translation>
            <numerusform>Dragging %n vertex %1 mm along Z. Release to finish, Esc cancels.</numerusform>
            <numerusform>Dragging %n vertices %1 mm along Z. Release to finish, Esc cancels.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_text.cpp" line="84"/>
        <source>Dragging %n vertices %1 mm in the view plane. Release to finish, Esc cancels; hold X, Y or Z to move along that axis.</source>
        <translation>
            <numerusform>Dragging %n vertex %1 mm in the view plane. Release to finish, Esc cancels; hold X, Y or Z to move along that axis.</numerusform>
            <numerusform>Dragging %n vertices %1 mm in the view plane. Release to finish, Esc cancels; hold X, Y or Z to move along that axis.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::ImportReferenceShapeReaction</name>
    <message numerus="yes">
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="136"/>
        <source>%n point(s)</source>
        <translation>
            <numerusform>%n point</numerusform>
            <numerusform>%n points</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="137"/>
        <source>%n triangle(s)</source>
        <translation>
            <numerusform>%n triangle</numerusform>
            <numerusform>%n triangles</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::JoinReaction</name>
    <message numerus="yes">
        <location filename="../app/gui/reactions/join_reaction.cpp" line="174"/>
        <source>No two of the %n surface(s) have boundary edges facing each other (within %1 % of their length); nothing was joined.</source>
        <translation>
            <numerusform>The %n surface has no boundary edges facing another (within %1 % of their length); nothing was joined.</numerusform>
            <numerusform>No two of the %n surfaces have boundary edges facing each other (within %1 % of their length); nothing was joined.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/join_reaction.cpp" line="201"/>
        <source>Joined %n surface(s) into one: </source>
        <translation>
            <numerusform>Joined %n surface into one: </numerusform>
            <numerusform>Joined %n surfaces into one: </numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/join_reaction.cpp" line="202"/>
        <source>%1 of %n pair(s) of facing edges welded</source>
        <translation>
            <numerusform>%1 of %n pair of facing edges welded</numerusform>
            <numerusform>%1 of %n pairs of facing edges welded</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/join_reaction.cpp" line="203"/>
        <source>, %n part(s) not connected</source>
        <translation>
            <numerusform>, %n part not connected</numerusform>
            <numerusform>, %n parts not connected</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/join_reaction.cpp" line="215"/>
        <source>%n surface(s) facing no other were left as they are.</source>
        <translation>
            <numerusform>%n surface facing no other was left as it is.</numerusform>
            <numerusform>%n surfaces facing no other were left as they are.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::MainWindow</name>
    <message numerus="yes">
        <location filename="../app/gui/main_window.cpp" line="501"/>
        <source>%n surface(s)</source>
        <translation>
            <numerusform>%n surface</numerusform>
            <numerusform>%n surfaces</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/main_window.cpp" line="502"/>
        <source>%n patch(es)</source>
        <translation>
            <numerusform>%n patch</numerusform>
            <numerusform>%n patches</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/main_window.cpp" line="503"/>
        <source>%n control point(s)</source>
        <translation>
            <numerusform>%n control point</numerusform>
            <numerusform>%n control points</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/main_window.cpp" line="504"/>
        <source>%n selected</source>
        <translation>
            <numerusform>%n selected</numerusform>
            <numerusform>%n selected</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/main_window_solver.cpp" line="34"/>
        <source>Make every surface developable again: %n iteration(s) of the solver, one undo step. Pinned vertices stay where they are.</source>
        <translation>
            <numerusform>Make every surface developable again: %n iteration of the solver, one undo step. Pinned vertices stay where they are.</numerusform>
            <numerusform>Make every surface developable again: %n iterations of the solver, one undo step. Pinned vertices stay where they are.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::MarkRegionTool</name>
    <message numerus="yes">
        <location filename="../app/gui/mark_region_tool.cpp" line="274"/>
        <source>%Ln point(s) of %1 marked.</source>
        <translation>
            <numerusform>%Ln point of %1 marked.</numerusform>
            <numerusform>%Ln points of %1 marked.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/mark_region_tool.cpp" line="276"/>
        <source>%Ln point(s) of the reference shapes marked.</source>
        <translation>
            <numerusform>%Ln point of the reference shapes marked.</numerusform>
            <numerusform>%Ln points of the reference shapes marked.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/mark_region_tool.cpp" line="325"/>
        <source>Added strip %1 over %Ln marked point(s); Tools ▸ Approximate Reference Shape… with the design&apos;s surfaces pulls it onto the shape.</source>
        <translation>
            <numerusform>Added strip %1 over %Ln marked point; Tools ▸ Approximate Reference Shape… with the design&apos;s surfaces pulls it onto the shape.</numerusform>
            <numerusform>Added strip %1 over %Ln marked points; Tools ▸ Approximate Reference Shape… with the design&apos;s surfaces pulls it onto the shape.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::PatchTreeModel</name>
    <message numerus="yes">
        <location filename="../app/gui/panels/patch_tree_model.cpp" line="120"/>
        <source>%n patch(es)</source>
        <translation>
            <numerusform>%n patch</numerusform>
            <numerusform>%n patches</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::PatternExportDialog</name>
    <message numerus="yes">
        <location filename="../app/gui/pattern_export_dialog.cpp" line="320"/>
        <source>%n piece(s)</source>
        <translation>
            <numerusform>%n piece</numerusform>
            <numerusform>%n pieces</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pattern_export_dialog.cpp" line="321"/>
        <source>%n sheet(s)</source>
        <translation>
            <numerusform>%n sheet</numerusform>
            <numerusform>%n sheets</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::PropertiesPanel</name>
    <message numerus="yes">
        <location filename="../app/gui/panels/properties_panel.cpp" line="128"/>
        <location filename="../app/gui/panels/properties_panel.cpp" line="138"/>
        <source>%n patch(es)</source>
        <translation>
            <numerusform>%n patch</numerusform>
            <numerusform>%n patches</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/panels/properties_panel.cpp" line="129"/>
        <source>%n control point(s)</source>
        <translation>
            <numerusform>%n control point</numerusform>
            <numerusform>%n control points</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/panels/properties_panel.cpp" line="137"/>
        <source>%n vertex(es)</source>
        <translation>
            <numerusform>%n vertex</numerusform>
            <numerusform>%n vertices</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/panels/properties_panel.cpp" line="137"/>
        <source>%n edge(s)</source>
        <translation>
            <numerusform>%n edge</numerusform>
            <numerusform>%n edges</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/panels/properties_panel.cpp" line="169"/>
        <source>Spline curve (S), %1, %n control point(s).&lt;br&gt;</source>
        <translation>
            <numerusform>Spline curve (S), %1, %n control point.&lt;br&gt;</numerusform>
            <numerusform>Spline curve (S), %1, %n control points.&lt;br&gt;</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/panels/properties_panel.cpp" line="198"/>
        <source>&lt;b&gt;Patch %1&lt;/b&gt;: %2&lt;br&gt;Edge labels along the patch: %3&lt;br&gt;%n corner(s).</source>
        <translation>
            <numerusform>&lt;b&gt;Patch %1&lt;/b&gt;: %2&lt;br&gt;Edge labels along the patch: %3&lt;br&gt;%n corner.</numerusform>
            <numerusform>&lt;b&gt;Patch %1&lt;/b&gt;: %2&lt;br&gt;Edge labels along the patch: %3&lt;br&gt;%n corners.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::RotateTool</name>
    <message numerus="yes">
        <location filename="../app/gui/rotate_tool.cpp" line="49"/>
        <source>Rotate %n vertices %1: move the mouse sideways, %2° per pixel.</source>
        <translation>
            <numerusform>Rotate %n vertex %1: move the mouse sideways, %2° per pixel.</numerusform>
            <numerusform>Rotate %n vertices %1: move the mouse sideways, %2° per pixel.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/rotate_tool.cpp" line="96"/>
        <source>Rotating %n vertices by %1° %2. Release to finish, Esc cancels.</source>
        <translation>
            <numerusform>Rotating %n vertex by %1° %2. Release to finish, Esc cancels.</numerusform>
            <numerusform>Rotating %n vertices by %1° %2. Release to finish, Esc cancels.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/rotate_tool.cpp" line="102"/>
        <source>Rotate %n vertices</source>
        <translation>
            <numerusform>Rotate %n vertex</numerusform>
            <numerusform>Rotate %n vertices</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::SheetShapeDialog</name>
    <message numerus="yes">
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="246"/>
        <source>%1: %n closed curve(s)</source>
        <translation>
            <numerusform>%1: %n closed curve</numerusform>
            <numerusform>%1: %n closed curves</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="325"/>
        <source>%n curve(s)</source>
        <translation>
            <numerusform>%n curve</numerusform>
            <numerusform>%n curves</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="328"/>
        <source>the creases as they lie: %n curve(s)</source>
        <translation>
            <numerusform>the creases as they lie: %n curve</numerusform>
            <numerusform>the creases as they lie: %n curves</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="345"/>
        <source>%1, holding %n crease(s)</source>
        <translation>
            <numerusform>%1, holding %n crease</numerusform>
            <numerusform>%1, holding %n creases</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="74"/>
        <source>%n closed curve(s)</source>
        <translation>
            <numerusform>%n closed curve</numerusform>
            <numerusform>%n closed curves</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::SolveController</name>
    <message numerus="yes">
        <location filename="../app/gui/solve_controller.cpp" line="208"/>
        <source>Check the shape: %n patch(es) fold over onto themselves (%1); undo, or pin or move differently.</source>
        <translation>
            <numerusform>Check the shape: %n patch folds over onto itself (%1); undo, or pin or move differently.</numerusform>
            <numerusform>Check the shape: %n patches fold over onto themselves (%1); undo, or pin or move differently.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_controller.cpp" line="215"/>
        <source>Check the shape: the development overlaps itself at %n patch(es) (%1); undo, or pin or move differently.</source>
        <translation>
            <numerusform>Check the shape: the development overlaps itself at %n patch (%1); undo, or pin or move differently.</numerusform>
            <numerusform>Check the shape: the development overlaps itself at %n patches (%1); undo, or pin or move differently.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_report_text.cpp" line="29"/>
        <location filename="../app/gui/solve_report_text.cpp" line="58"/>
        <source>folded over in %n place(s)</source>
        <translation>
            <numerusform>folded over in %n place</numerusform>
            <numerusform>folded over in %n places</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_report_text.cpp" line="61"/>
        <source>left a development overlapping itself at %n patch(es)</source>
        <translation>
            <numerusform>left a development overlapping itself at %n patch</numerusform>
            <numerusform>left a development overlapping itself at %n patches</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_report_text.cpp" line="243"/>
        <source>; %n patch(es) fold over onto themselves, where the surface overlaps itself: %1</source>
        <translation>
            <numerusform>; %n patch folds over onto itself, where the surface overlaps itself: %1</numerusform>
            <numerusform>; %n patches fold over onto themselves, where the surface overlaps itself: %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_report_text.cpp" line="258"/>
        <source>; the development overlaps itself at %n patch(es) (%1) and cannot be cut from one sheet</source>
        <translation>
            <numerusform>; the development overlaps itself at %n patch (%1) and cannot be cut from one sheet</numerusform>
            <numerusform>; the development overlaps itself at %n patches (%1) and cannot be cut from one sheet</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_controller.cpp" line="344"/>
        <source>Solved: %n iteration(s), largest constraint residual %1.</source>
        <translation>
            <numerusform>Solved: %n iteration, largest constraint residual %1.</numerusform>
            <numerusform>Solved: %n iterations, largest constraint residual %1.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_controller.cpp" line="351"/>
        <source>%n surface(s) left as they were: solving made them less developable.</source>
        <translation>
            <numerusform>%n surface left as it was: solving made it less developable.</numerusform>
            <numerusform>%n surfaces left as they were: solving made them less developable.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_controller.cpp" line="387"/>
        <source>%1, kept developable: %n iteration(s), largest constraint residual %2.</source>
        <translation>
            <numerusform>%1, kept developable: %n iteration, largest constraint residual %2.</numerusform>
            <numerusform>%1, kept developable: %n iterations, largest constraint residual %2.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::SolverPanel</name>
    <message numerus="yes">
        <location filename="../app/gui/panels/solver_panel.cpp" line="152"/>
        <source>&lt;b&gt;%1&lt;/b&gt;: %2&lt;br&gt;%n iteration(s) in %3 ms.</source>
        <translation>
            <numerusform>&lt;b&gt;%1&lt;/b&gt;: %2&lt;br&gt;%n iteration in %3 ms.</numerusform>
            <numerusform>&lt;b&gt;%1&lt;/b&gt;: %2&lt;br&gt;%n iterations in %3 ms.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::SplitAtRulingReaction</name>
    <message numerus="yes">
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="238"/>
        <source>Where the new ruling crosses patch %1 and the strips that share its curves (green in the 3D view): per cent of the way along the strip. Rulings can go through the %n breakpoint(s) of the curves; refine the curves (Ctrl+Shift+R) for more.</source>
        <translation>
            <numerusform>Where the new ruling crosses patch %1 and the strips that share its curves (green in the 3D view): per cent of the way along the strip. Rulings can go through the %n breakpoint of the curves; refine the curves (Ctrl+Shift+R) for more.</numerusform>
            <numerusform>Where the new ruling crosses patch %1 and the strips that share its curves (green in the 3D view): per cent of the way along the strip. Rulings can go through the %n breakpoints of the curves; refine the curves (Ctrl+Shift+R) for more.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::Workspace</name>
    <message numerus="yes">
        <location filename="../app/gui/workspace.cpp" line="86"/>
        <source>… and %n more problem(s).</source>
        <translation>
            <numerusform>… and %n more problem.</numerusform>
            <numerusform>… and %n more problems.</numerusform>
        </translation>
    </message>
</context>
</TS>
