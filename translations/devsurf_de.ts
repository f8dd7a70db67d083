<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="de_DE">
<context>
    <name>ApplySurfaceCommand</name>
    <message>
        <location filename="../model/document/commands/apply_surface_command.cpp" line="20" />
        <source>The new shape cannot be applied: %1</source>
        <translation>Die neue Form kann nicht übernommen werden: %1</translation>
    </message>
</context>
<context>
    <name>FaceType</name>
    <message>
        <location filename="../app/gui/face_type_text.cpp" line="10" />
        <source>strip (SRSR)</source>
        <translation>Streifen (SRSR)</translation>
    </message>
    <message>
        <location filename="../app/gui/face_type_text.cpp" line="12" />
        <source>pointed strip (SRS)</source>
        <translation>spitzer Streifen (SRS)</translation>
    </message>
    <message>
        <location filename="../app/gui/face_type_text.cpp" line="14" />
        <source>cone (SRR)</source>
        <translation>Kegel (SRR)</translation>
    </message>
    <message>
        <location filename="../app/gui/face_type_text.cpp" line="16" />
        <source>planar face</source>
        <translation>ebene Fläche</translation>
    </message>
    <message>
        <location filename="../app/gui/face_type_text.cpp" line="20" />
        <source>invalid labelling</source>
        <translation>ungültige Beschriftung</translation>
    </message>
</context>
<context>
    <name>MoveVerticesCommand</name>
    <message>
        <location filename="../model/document/commands/move_vertices_command.cpp" line="20" />
        <source>The vertices cannot be moved by an offset that is not a finite number.</source>
        <translation>Die Ecken können nicht um einen Versatz verschoben werden, der keine endliche Zahl ist.</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/move_vertices_command.cpp" line="23" />
        <source>Move %n vertices</source>
        <translation><numerusform>%n Ecke verschieben</numerusform><numerusform>%n Ecken verschieben</numerusform></translation>
    </message>
    <message>
        <location filename="../model/document/commands/move_vertices_command.cpp" line="37" />
        <source>The vertices cannot be rotated: %1</source>
        <translation>Die Ecken können nicht gedreht werden: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/move_vertices_command.cpp" line="39" />
        <source>Rotate %n vertices</source>
        <translation><numerusform>%n Ecke drehen</numerusform><numerusform>%n Ecken drehen</numerusform></translation>
    </message>
    <message>
        <location filename="../model/document/commands/move_vertices_command.cpp" line="47" />
        <source>The vertices cannot be moved</source>
        <translation>Die Ecken können nicht verschoben werden</translation>
    </message>
</context>
<context>
    <name>RefineSplineClassCommand</name>
    <message>
        <location filename="../model/document/commands/refine_spline_class_command.cpp" line="9" />
        <source>Refine curves</source>
        <translation>Kurven verfeinern</translation>
    </message>
    <message>
        <location filename="../model/document/commands/refine_spline_class_command.cpp" line="11" />
        <source>The curves of edge %1 cannot be refined</source>
        <translation>Die Kurven der Kante %1 können nicht verfeinert werden</translation>
    </message>
</context>
<context>
    <name>RelabelEdgeCommand</name>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="16" />
        <source>Select at least one edge to relabel.</source>
        <translation>Wählen Sie mindestens eine Kante zum Umbenennen aus.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="23" />
        <source>Make edge %1 a spline curve</source>
        <translation>Kante %1 zur Splinekurve machen</translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="24" />
        <source>Make edge %1 a ruling</source>
        <translation>Kante %1 zur Erzeugenden machen</translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="25" />
        <source>Edge %1 cannot become a spline curve</source>
        <translation>Kante %1 kann keine Splinekurve werden</translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="26" />
        <source>Edge %1 cannot become a ruling</source>
        <translation>Kante %1 kann keine Erzeugende werden</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="28" />
        <source>Relabel %n edges</source>
        <translation><numerusform>%n Kante umbenennen</numerusform><numerusform>%n Kanten umbenennen</numerusform></translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="29" />
        <source>The edges cannot be relabelled</source>
        <translation>Die Kanten können nicht umbenannt werden</translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="39" />
        <source>Edge %1 is already a spline curve.</source>
        <translation>Kante %1 ist bereits eine Splinekurve.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="40" />
        <source>Edge %1 is already a ruling.</source>
        <translation>Kante %1 ist bereits eine Erzeugende.</translation>
    </message>
</context>
<context>
    <name>SplitAtRulingCommand</name>
    <message>
        <location filename="../model/document/commands/split_at_ruling_command.cpp" line="12" />
        <source>Add a ruling to face %1</source>
        <translation>Erzeugende in Fläche %1 einfügen</translation>
    </message>
    <message>
        <location filename="../model/document/commands/split_at_ruling_command.cpp" line="14" />
        <source>No ruling can be added to face %1</source>
        <translation>In Fläche %1 kann keine Erzeugende eingefügt werden</translation>
    </message>
</context>
<context>
    <name>SubdivideStripCommand</name>
    <message>
        <location filename="../model/document/commands/subdivide_strip_command.cpp" line="9" />
        <source>Subdivide strip %1</source>
        <translation>Streifen %1 unterteilen</translation>
    </message>
    <message>
        <location filename="../model/document/commands/subdivide_strip_command.cpp" line="11" />
        <source>Strip %1 cannot be subdivided</source>
        <translation>Streifen %1 kann nicht unterteilt werden</translation>
    </message>
</context>
<context>
    <name>SurfaceEditCommand</name>
    <message>
        <location filename="../model/document/commands/surface_edit_command.cpp" line="38" />
        <source>There is no surface number %1 in the design.</source>
        <translation>Der Entwurf hat keine Fläche Nummer %1.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/surface_edit_command.cpp" line="56" />
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>devsurf::app::DeleteSelectionReaction</name>
    <message>
        <location filename="../app/gui/reactions/edit_reactions.cpp" line="10" />
        <source>Deleting parts of a surface is not available yet: relabel an edge (Ctrl+L) or undo (Ctrl+Z) instead.</source>
        <translation>Teile einer Fläche zu löschen ist noch nicht möglich: Benennen Sie stattdessen eine Kante um (Strg+L) oder machen Sie rückgängig (Strg+Z).</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ExampleDialog</name>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="19" />
        <source>A flat rectangle of size × size strips.</source>
        <translation>Ein ebenes Rechteck aus Größe × Größe Streifen.</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="22" />
        <source>A flat annulus of size rings cut by radial rulings.</source>
        <translation>Ein ebener Kreisring aus Größe Ringen, geteilt durch radiale Erzeugende.</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="25" />
        <source>A closed cylinder of strips, size sectors around.</source>
        <translation>Ein geschlossener Zylinder aus Streifen, Größe Sektoren im Umfang.</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="27" />
        <source>A strip, a pointed strip, a cone and a planar face; size intervals per curve.</source>
        <translation>Ein Streifen, ein spitzer Streifen, ein Kegel und eine ebene Fläche; Größe Intervalle je Kurve.</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="36" />
        <source>New from Example</source>
        <translation>Neu aus Beispiel</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="42" />
        <source>&amp;Example:</source>
        <translation>&amp;Beispiel:</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="43" />
        <source>&amp;Size:</source>
        <translation>&amp;Größe:</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ExportJsonReaction</name>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="80" />
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="82" />
        <source>Export Interchange JSON</source>
        <translation>Austausch-JSON exportieren</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="84" />
        <source>Interchange JSON (*.json)</source>
        <translation>Austausch-JSON (*.json)</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="92" />
        <location filename="../app/gui/reactions/file_reactions.cpp" line="95" />
        <source>Export failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="90" />
        <source>Exported %1</source>
        <translation>%1 exportiert</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="96" />
        <source>The design cannot be exported: %1</source>
        <translation>Der Entwurf kann nicht exportiert werden: %1</translation>
    </message>
</context>
<context>
    <name>devsurf::app::MainWindow</name>
    <message>
        <location filename="../app/gui/main_window.cpp" line="101" />
        <source>Patches</source>
        <translation>Flächenstücke</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="107" />
        <source>Properties</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="114" />
        <source>Main</source>
        <translation>Haupt</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="119" />
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="121" />
        <source>&amp;New from Example…</source>
        <translation>&amp;Neu aus Beispiel…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="123" />
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="125" />
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="129" />
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="132" />
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="136" />
        <source>&amp;Export Interchange JSON…</source>
        <translation>Austausch-JSON &amp;exportieren…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="136" />
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="139" />
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="143" />
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="146" />
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="149" />
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="156" />
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="158" />
        <source>Select &amp;None</source>
        <translation>Auswahl &amp;aufheben</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="159" />
        <source>Esc</source>
        <translation>Esc</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="163" />
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="165" />
        <source>&amp;3D View</source>
        <translation>&amp;3D-Ansicht</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="165" />
        <source>Ctrl+1</source>
        <translation>Ctrl+1</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="167" />
        <source>&amp;Development View</source>
        <translation>&amp;Abwicklung</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="167" />
        <source>Ctrl+2</source>
        <translation>Ctrl+2</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="168" />
        <source>3D &amp;and Development</source>
        <translation>3D &amp;und Abwicklung</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="169" />
        <source>Ctrl+3</source>
        <translation>Ctrl+3</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="173" />
        <source>&amp;Control Polygons</source>
        <translation>&amp;Kontrollpolygone</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="173" />
        <source>Ctrl+Shift+P</source>
        <translation>Ctrl+Shift+P</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="174" />
        <source>&amp;Vertices</source>
        <translation>&amp;Ecken</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="175" />
        <source>Ctrl+Shift+V</source>
        <translation>Ctrl+Shift+V</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="178" />
        <source>&amp;Fit All</source>
        <translation>&amp;Alles zeigen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="178" />
        <source>F</source>
        <translation>F</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="184" />
        <source>&amp;Tools</source>
        <translation>&amp;Werkzeuge</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="186" />
        <source>&amp;Relabel Edge (R ↔ S)</source>
        <translation>Kante &amp;umbenennen (R ↔ S)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="186" />
        <source>Ctrl+L</source>
        <translation>Ctrl+L</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="189" />
        <source>&amp;Subdivide Strip with a Crease…</source>
        <translation>Streifen mit Falz &amp;unterteilen…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="190" />
        <source>Ctrl+D</source>
        <translation>Ctrl+D</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="193" />
        <source>Split at &amp;Ruling…</source>
        <translation>An &amp;Erzeugender teilen…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="193" />
        <source>Ctrl+R</source>
        <translation>Ctrl+R</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="195" />
        <source>Re&amp;fine Curves</source>
        <translation>Kurven &amp;verfeinern</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="196" />
        <source>Ctrl+Shift+R</source>
        <translation>Ctrl+Shift+R</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="200" />
        <source>&amp;Move or Rotate Vertices…</source>
        <translation>Ecken &amp;verschieben oder drehen…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="200" />
        <source>Ctrl+M</source>
        <translation>Ctrl+M</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="204" />
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="205" />
        <source>&amp;About DevSurf</source>
        <translation>&amp;Über DevSurf</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="207" />
        <source>About DevSurf</source>
        <translation>Über DevSurf</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="208" />
        <source>&lt;b&gt;DevSurf %1&lt;/b&gt;&lt;p&gt;Design of developable surfaces and curved-crease origami with spline developables (Tang, Bo, Wallner, Pottmann 2015).&lt;/p&gt;</source>
        <translation>&lt;b&gt;DevSurf %1&lt;/b&gt;&lt;p&gt;Entwurf abwickelbarer Flächen und Origami mit gekrümmten Falzen mit Spline-Torsen (Tang, Bo, Wallner, Pottmann 2015).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="236" />
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="237" />
        <source>%1[*] — DevSurf</source>
        <translation>%1[*] — DevSurf</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="250" />
        <source>%1 surfaces · %2 patches · %3 control points · %4 selected</source>
        <translation>%1 Flächen · %2 Flächenstücke · %3 Kontrollpunkte · %4 ausgewählt</translation>
    </message>
</context>
<context>
    <name>devsurf::app::MoveDialog</name>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="37" />
        <source>&amp;Translate</source>
        <translation>&amp;Verschieben</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="38" />
        <source>&amp;Rotate</source>
        <translation>&amp;Drehen</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="39" />
        <source>Move or Rotate Vertices</source>
        <translation>Ecken verschieben oder drehen</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="42" />
        <source>Translation</source>
        <translation>Verschiebung</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="44" />
        <source>Offset (x, y, z):</source>
        <translation>Versatz (x, y, z):</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="47" />
        <source>Rotation</source>
        <translation>Drehung</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="49" />
        <source>Axis through (x, y, z):</source>
        <translation>Achse durch (x, y, z):</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="51" />
        <source>Axis direction:</source>
        <translation>Achsrichtung:</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="55" />
        <source>Angle:</source>
        <translation>Winkel:</translation>
    </message>
</context>
<context>
    <name>devsurf::app::MoveVerticesReaction</name>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="243" />
        <source>Translate or rotate the selected vertices with their neighbouring control points. Select vertices of one surface first.</source>
        <translation>Verschiebt oder dreht die ausgewählten Ecken samt benachbarten Kontrollpunkten. Wählen Sie zuerst Ecken einer Fläche aus.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="269" />
        <source>Cannot rotate</source>
        <translation>Drehen nicht möglich</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="273" />
        <source>Cannot move</source>
        <translation>Verschieben nicht möglich</translation>
    </message>
</context>
<context>
    <name>devsurf::app::OpenReaction</name>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="30" />
        <source>Open Project</source>
        <translation>Projekt öffnen</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="32" />
        <source>DevSurf projects (*.devsurf)</source>
        <translation>DevSurf-Projekte (*.devsurf)</translation>
    </message>
</context>
<context>
    <name>devsurf::app::OpenRecentReaction</name>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="60" />
        <source>No recent files</source>
        <translation>Keine zuletzt geöffneten Dateien</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="64" />
        <source>Clear Recent Files</source>
        <translation>Liste leeren</translation>
    </message>
</context>
<context>
    <name>devsurf::app::PatchTreeModel</name>
    <message numerus="yes">
        <location filename="../app/gui/panels/patch_tree_model.cpp" line="120" />
        <source>%n patches</source>
        <translation><numerusform>%n Flächenstück</numerusform><numerusform>%n Flächenstücke</numerusform></translation>
    </message>
    <message>
        <location filename="../app/gui/panels/patch_tree_model.cpp" line="129" />
        <source>Patch %1</source>
        <translation>Flächenstück %1</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/patch_tree_model.cpp" line="133" />
        <source>invalid labelling %1</source>
        <translation>ungültige Beschriftung %1</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/patch_tree_model.cpp" line="142" />
        <source>Edge labels along the patch: %1</source>
        <translation>Kantenbeschriftung entlang des Flächenstücks: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/patch_tree_model.cpp" line="152" />
        <source>Patch</source>
        <translation>Flächenstück</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/patch_tree_model.cpp" line="152" />
        <source>Type</source>
        <translation>Typ</translation>
    </message>
</context>
<context>
    <name>devsurf::app::PropertiesPanel</name>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="22" />
        <source>degree %1, C%2, %3 intervals</source>
        <translation>Grad %1, C%2, %3 Intervalle</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="76" />
        <source>Nothing selected.&lt;br&gt;%1 patches, %2 control points.&lt;br&gt;&lt;i&gt;Click a vertex, edge or patch to select it; Shift-click adds to the selection.&lt;/i&gt;</source>
        <translation>Nichts ausgewählt.&lt;br&gt;%1 Flächenstücke, %2 Kontrollpunkte.&lt;br&gt;&lt;i&gt;Klicken Sie auf eine Ecke, Kante oder ein Flächenstück, um es auszuwählen; Umschalt-Klick erweitert die Auswahl.&lt;/i&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="85" />
        <source>%1 vertices, %2 edges, %3 patches selected.</source>
        <translation>%1 Ecken, %2 Kanten, %3 Flächenstücke ausgewählt.</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="101" />
        <source>&lt;b&gt;Vertex %1&lt;/b&gt;</source>
        <translation>&lt;b&gt;Ecke %1&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="112" />
        <source>&lt;b&gt;Edge %1&lt;/b&gt; from vertex %2 to vertex %3&lt;br&gt;</source>
        <translation>&lt;b&gt;Kante %1&lt;/b&gt; von Ecke %2 zu Ecke %3&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="117" />
        <source>Spline curve (S), %1, %2 control points.&lt;br&gt;</source>
        <translation>Splinekurve (S), %1, %2 Kontrollpunkte.&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="120" />
        <source>A crease between patches %1 and %2; condition: %3.</source>
        <translation>Ein Falz zwischen den Flächenstücken %1 und %2; Bedingung: %3.</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="126" />
        <source>A boundary curve of patch %1.</source>
        <translation>Eine Randkurve des Flächenstücks %1.</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="129" />
        <source>Ruling (R), a straight segment of length %1 mm.</source>
        <translation>Erzeugende (R), eine Strecke der Länge %1 mm.</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="138" />
        <source>&lt;b&gt;Patch %1&lt;/b&gt;: %2&lt;br&gt;Edge labels along the patch: %3&lt;br&gt;%4 corners.</source>
        <translation>&lt;b&gt;Flächenstück %1&lt;/b&gt;: %2&lt;br&gt;Kantenbeschriftung entlang des Flächenstücks: %3&lt;br&gt;%4 Ecken.</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="173" />
        <source>Cannot move</source>
        <translation>Verschieben nicht möglich</translation>
    </message>
</context>
<context>
    <name>devsurf::app::RefineCurvesReaction</name>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="222" />
        <source>Double the spline intervals of the selected curve and of all curves joined to it through strips; the shape stays the same. Select one spline edge or strip first.</source>
        <translation>Verdoppelt die Spline-Intervalle der ausgewählten Kurve und aller über Streifen mit ihr verbundenen Kurven; die Form bleibt gleich. Wählen Sie zuerst eine Splinekante oder einen Streifen aus.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="232" />
        <source>Cannot refine</source>
        <translation>Verfeinern nicht möglich</translation>
    </message>
</context>
<context>
    <name>devsurf::app::RelabelEdgeReaction</name>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="85" />
        <source>Turn the selected edges from rulings (R) into spline curves (S) or back. Select edges of one surface first.</source>
        <translation>Macht die ausgewählten Kanten von Erzeugenden (R) zu Splinekurven (S) oder umgekehrt. Wählen Sie zuerst Kanten einer Fläche aus.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="105" />
        <source>Cannot relabel</source>
        <translation>Umbenennen nicht möglich</translation>
    </message>
</context>
<context>
    <name>devsurf::app::SplitAtRulingReaction</name>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="147" />
        <source>Add a ruling across the selected strip and the strips that share its curves. Select one strip or cone first.</source>
        <translation>Fügt eine Erzeugende quer über den ausgewählten Streifen und die Streifen mit denselben Kurven ein. Wählen Sie zuerst einen Streifen oder Kegel aus.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="166" />
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="179" />
        <source>Split at Ruling</source>
        <translation>An Erzeugender teilen</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="167" />
        <source>The curves of this strip have a single spline interval, so a ruling can only be added after refining them (the shape stays the same). Refine now?</source>
        <translation>Die Kurven dieses Streifens haben nur ein Spline-Intervall; eine Erzeugende kann erst nach dem Verfeinern eingefügt werden (die Form bleibt gleich). Jetzt verfeinern?</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="172" />
        <source>Cannot refine</source>
        <translation>Verfeinern nicht möglich</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="180" />
        <source>The new ruling goes through breakpoint i of the strip's %1 spline intervals (u = i/%1). Breakpoint i:</source>
        <translation>Die neue Erzeugende geht durch den Knoten i der %1 Spline-Intervalle des Streifens (u = i/%1). Knoten i:</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="189" />
        <source>Cannot split</source>
        <translation>Teilen nicht möglich</translation>
    </message>
</context>
<context>
    <name>devsurf::app::SubdivideStripReaction</name>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="115" />
        <source>Add a crease across the selected strip and the row of strips it belongs to. Select one SRSR strip first.</source>
        <translation>Fügt einen Falz quer über den ausgewählten Streifen und seine Streifenreihe ein. Wählen Sie zuerst einen SRSR-Streifen aus.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="126" />
        <source>Subdivide Strip</source>
        <translation>Streifen unterteilen</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="127" />
        <source>Position of the new crease between the strip's curve a (0) and curve b (1):</source>
        <translation>Lage des neuen Falzes zwischen der Kurve a (0) und der Kurve b (1) des Streifens:</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="134" />
        <source>Cannot subdivide</source>
        <translation>Unterteilen nicht möglich</translation>
    </message>
</context>
<context>
    <name>devsurf::app::Workspace</name>
    <message>
        <location filename="../app/gui/workspace.cpp" line="82" />
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="85" />
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="86" />
        <source>%1 has unsaved changes. Do you want to save them?</source>
        <translation>%1 hat ungespeicherte Änderungen. Möchten Sie sie speichern?</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="100" />
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="103" />
        <source>Cannot open file</source>
        <translation>Datei kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="117" />
        <source>Save Project As</source>
        <translation>Projekt speichern unter</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="120" />
        <source>untitled.devsurf</source>
        <translation>unbenannt.devsurf</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="122" />
        <source>DevSurf projects (*.devsurf)</source>
        <translation>DevSurf-Projekte (*.devsurf)</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="136" />
        <source>Cannot save file</source>
        <translation>Datei kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="143" />
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="150" />
        <source>New design from the example “%1”</source>
        <translation>Neuer Entwurf aus dem Beispiel „%1“</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="152" />
        <source>Cannot create the example</source>
        <translation>Das Beispiel kann nicht erzeugt werden</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="163" />
        <source>Recovered unsaved work</source>
        <translation>Ungespeicherte Arbeit wiederhergestellt</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="166" />
        <source>Cannot recover</source>
        <translation>Wiederherstellen nicht möglich</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="179" />
        <source>an untitled design</source>
        <translation>einem unbenannten Entwurf</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="181" />
        <source>Recover unsaved work</source>
        <translation>Ungespeicherte Arbeit wiederherstellen</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="182" />
        <source>DevSurf did not close properly last time. Recover the unsaved changes to %1 from %2?</source>
        <translation>DevSurf wurde zuletzt nicht ordnungsgemäß beendet. Die ungespeicherten Änderungen an %1 vom %2 wiederherstellen?</translation>
    </message>
</context>
<context>
    <name>devsurf::views::SceneView</name>
    <message>
        <location filename="../views/scene_view.cpp" line="232" />
        <source>Surface %1 is not valid and is not shown.</source>
        <translation>Fläche %1 ist ungültig und wird nicht angezeigt.</translation>
    </message>
    <message>
        <location filename="../views/scene_view.cpp" line="254" />
        <source>vertex %1</source>
        <translation>Ecke %1</translation>
    </message>
    <message>
        <location filename="../views/scene_view.cpp" line="263" />
        <source>edge %1 (R)</source>
        <translation>Kante %1 (R)</translation>
    </message>
    <message>
        <location filename="../views/scene_view.cpp" line="265" />
        <source>edge %1 (S, crease)</source>
        <translation>Kante %1 (S, Falz)</translation>
    </message>
    <message>
        <location filename="../views/scene_view.cpp" line="267" />
        <source>edge %1 (S, boundary)</source>
        <translation>Kante %1 (S, Rand)</translation>
    </message>
    <message>
        <location filename="../views/scene_view.cpp" line="278" />
        <source>SRSR strip</source>
        <translation>SRSR-Streifen</translation>
    </message>
    <message>
        <location filename="../views/scene_view.cpp" line="281" />
        <source>SRS strip</source>
        <translation>SRS-Streifen</translation>
    </message>
    <message>
        <location filename="../views/scene_view.cpp" line="284" />
        <source>SRR cone</source>
        <translation>SRR-Kegel</translation>
    </message>
    <message>
        <location filename="../views/scene_view.cpp" line="287" />
        <source>planar polygon</source>
        <translation>ebenes Polygon</translation>
    </message>
    <message>
        <location filename="../views/scene_view.cpp" line="290" />
        <source>invalid face</source>
        <translation>ungültige Fläche</translation>
    </message>
    <message>
        <location filename="../views/scene_view.cpp" line="293" />
        <source>face %1 (%2)</source>
        <translation>Fläche %1 (%2)</translation>
    </message>
    <message>
        <location filename="../views/scene_view.cpp" line="298" />
        <source>surface %1: %2</source>
        <translation>Fläche %1: %2</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="38" />
        <source>Design developable surfaces and curved-crease origami.</source>
        <translation>Entwurf abwickelbarer Flächen und Origami mit gekrümmten Falzen.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="42" />
        <source>A project file to open.</source>
        <translation>Eine zu öffnende Projektdatei.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="45" />
        <source>Start with a built-in example.</source>
        <translation>Mit einem eingebauten Beispiel beginnen.</translation>
    </message>
</context>
</TS>