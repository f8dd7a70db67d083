<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name></name>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="34"/>
        <source>%1 is not a file DevSurf reads shapes from; choose a mesh (OBJ, PLY, STL, OFF) or a point cloud (XYZ, PTS).</source>
        <translation>%1 ist keine Datei, aus der DevSurf Formen liest; wählen Sie ein Netz (OBJ, PLY, STL, OFF) oder eine Punktwolke (XYZ, PTS).</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="38"/>
        <source>%1 cannot be read; check that it exists and that you may read it.</source>
        <translation>%1 kann nicht gelesen werden; prüfen Sie, ob die Datei existiert und Sie sie lesen dürfen.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="40"/>
        <source>%1 is too large; DevSurf takes up to %2 points and %3 triangles.</source>
        <translation>%1 ist zu groß; DevSurf nimmt bis zu %2 Punkte und %3 Dreiecke.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="44"/>
        <source>%1 is damaged or not a valid file of its type; nothing was imported.</source>
        <translation>%1 ist beschädigt oder keine gültige Datei ihres Typs; nichts wurde importiert.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="47"/>
        <source>%1 ends before its last point or triangle; copy or export it again.</source>
        <translation>%1 endet vor ihrem letzten Punkt oder Dreieck; kopieren oder exportieren Sie sie erneut.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="50"/>
        <source>%1 holds a coordinate that is not a finite number of sensible size; nothing was imported.</source>
        <translation>%1 enthält eine Koordinate, die keine endliche Zahl sinnvoller Größe ist; nichts wurde importiert.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="54"/>
        <source>A face of %1 names a point the file does not have; nothing was imported.</source>
        <translation>Eine Fläche von %1 nennt einen Punkt, den die Datei nicht hat; nichts wurde importiert.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="57"/>
        <source>%1 holds no points to import.</source>
        <translation>%1 enthält keine Punkte zum Importieren.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="61"/>
        <source>No reference shape could be imported from %1.</source>
        <translation>Aus %1 konnte keine Referenzform importiert werden.</translation>
    </message>
</context>
<context>
    <name>AddSurfacesCommand</name>
    <message>
        <location filename="../model/document/commands/add_surfaces_command.cpp" line="19"/>
        <source>There is no surface to add.</source>
        <translation>Es gibt keine Fläche zum Hinzufügen.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/add_surfaces_command.cpp" line="24"/>
        <source>A surface to add is not valid.</source>
        <translation>Eine hinzuzufügende Fläche ist nicht gültig.</translation>
    </message>
</context>
<context>
    <name>ApplySurfaceCommand</name>
    <message>
        <location filename="../model/document/commands/apply_surface_command.cpp" line="20"/>
        <source>The new shape cannot be applied</source>
        <translation>Die neue Form kann nicht übernommen werden</translation>
    </message>
</context>
<context>
    <name>BoundedPattern</name>
    <message>
        <location filename="../app/gui/bounded_pattern.cpp" line="25"/>
        <source>Surface %1 reaches %2 m from the origin: even at a tolerance of 10 mm its pattern would take minutes to build, so there is none. Move its far control points closer.</source>
        <translation>Fläche %1 reicht %2 m vom Ursprung weg: Selbst bei einer Toleranz von 10 mm würde ihr Schnittmuster Minuten brauchen, daher gibt es keines. Rücken Sie ihre fernen Kontrollpunkte näher heran.</translation>
    </message>
    <message>
        <location filename="../app/gui/bounded_pattern.cpp" line="38"/>
        <source>Surface %1 reaches %2 m from the origin: its curves are sampled to %3 mm, since %4 mm would take minutes.</source>
        <translation>Fläche %1 reicht %2 m vom Ursprung weg: Ihre Kurven werden auf %3 mm abgetastet, da %4 mm Minuten dauern würde.</translation>
    </message>
</context>
<context>
    <name>CreaseConditionCommand</name>
    <message>
        <location filename="../model/document/commands/crease_condition_command.cpp" line="8"/>
        <source>Curved fold</source>
        <translation>Gekrümmte Faltung</translation>
    </message>
    <message>
        <location filename="../model/document/commands/crease_condition_command.cpp" line="10"/>
        <source>Geodesic</source>
        <translation>Geodätische</translation>
    </message>
    <message>
        <location filename="../model/document/commands/crease_condition_command.cpp" line="12"/>
        <source>Straight when unfolded</source>
        <translation>Gerade in der Abwicklung</translation>
    </message>
    <message>
        <location filename="../model/document/commands/crease_condition_command.cpp" line="16"/>
        <source>No condition</source>
        <translation>Keine Bedingung</translation>
    </message>
    <message>
        <location filename="../model/document/commands/crease_condition_command.cpp" line="24"/>
        <source>Select at least one crease.</source>
        <translation>Wählen Sie mindestens einen Falz.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/crease_condition_command.cpp" line="34"/>
        <source>Edge %1 does not exist.</source>
        <translation>Kante %1 gibt es nicht.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/crease_condition_command.cpp" line="38"/>
        <source>Edge %1 is a ruling; conditions apply to creases (curves between two patches).</source>
        <translation>Kante %1 ist eine Erzeugende; Bedingungen gelten für Falze (Kurven zwischen zwei Flächenstücken).</translation>
    </message>
    <message>
        <location filename="../model/document/commands/crease_condition_command.cpp" line="44"/>
        <source>Edge %1 is a curve on the boundary, not a crease; conditions apply to curves between two patches.</source>
        <translation>Kante %1 ist eine Randkurve, kein Falz; Bedingungen gelten für Kurven zwischen zwei Flächenstücken.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/crease_condition_command.cpp" line="51"/>
        <source>The selected creases already have the condition &quot;%1&quot;.</source>
        <translation>Die gewählten Falze haben bereits die Bedingung „%1“.</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/crease_condition_command.cpp" line="55"/>
        <source>Clear the condition of %n creases</source>
        <translation>
            <numerusform>Bedingung von %n Falz entfernen</numerusform>
            <numerusform>Bedingung von %n Falzen entfernen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/crease_condition_command.cpp" line="56"/>
        <source>%1 on %n creases</source>
        <translation>
            <numerusform>%1 auf %n Falz</numerusform>
            <numerusform>%1 auf %n Falzen</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>EditRefusal</name>
    <message>
        <location filename="../app/gui/edit_refusal.cpp" line="17"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>ExampleDialog</name>
    <message>
        <location filename="../app/text/example_text.cpp" line="9"/>
        <source>A flat rectangle of size × size strips.</source>
        <translation>Ein ebenes Rechteck aus Größe × Größe Streifen.</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="13"/>
        <source>A flat annulus of size rings cut by radial rulings.</source>
        <translation>Ein ebener Kreisring aus Größe Ringen, geteilt durch radiale Erzeugende.</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="17"/>
        <source>A closed cylinder of strips, size sectors around.</source>
        <translation>Ein geschlossener Zylinder aus Streifen, Größe Sektoren im Umfang.</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="21"/>
        <source>A flat square of size × size strips with curved creases, ready to fold: every interior crease carries the curved-fold condition and the bottom corners are pinned. Drag the middle vertices up (Drag tool, G).</source>
        <translation>Ein ebenes Quadrat aus Größe × Größe Streifen mit gekrümmten Falzen, bereit zum Falten: Jeder innere Falz trägt die Bedingung „Gekrümmte Faltung“, und die unteren Ecken sind festgehalten. Ziehen Sie die mittleren Ecken nach oben (Ziehwerkzeug, G).</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="28"/>
        <source>Two strips joined by one curved crease with the curved-fold condition, the bottom corners pinned; size intervals per curve. Drag a top corner up to fold it.</source>
        <translation>Zwei Streifen, verbunden durch einen gekrümmten Falz mit der Bedingung „Gekrümmte Faltung“, die unteren Ecken festgehalten; Größe Intervalle je Kurve. Ziehen Sie eine obere Ecke nach oben, um ihn zu falten.</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="34"/>
        <source>A disk with one curved crease between two strips, folded from a disk-shaped sheet it keeps; the crease&apos;s middle and the rim below it pinned; size faces per strip. Drag the top of the rim up and in towards the crease to fold it.</source>
        <translation>Eine Kreisscheibe mit einem gekrümmten Falz zwischen zwei Streifen, gefaltet aus einem kreisförmigen Bogen, den sie festhält; die Mitte des Falzes und der Randpunkt darunter fixiert; size Flächenstücke je Streifen. Ziehen Sie den obersten Randpunkt nach oben und zum Falz hin, um die Scheibe zu falten.</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="41"/>
        <source>A ring of size bands folded along concentric curved creases, mountain and valley in turn, exactly: every crease a fold in a horizontal plane, every band a piece of one cone. It keeps its development on its sheet, a ring whose edges wave with its eight lobes; three inner vertices pinned.</source>
        <translation>Ein Ring aus size Bändern, entlang konzentrischer gekrümmter Falten abwechselnd als Berg- und Talfalte exakt gefaltet: jede Falte eine Faltung in einer waagerechten Ebene, jedes Band ein Stück eines Kegels. Er behält seine Abwicklung auf seinem Blatt, einem Ring, dessen Ränder sich mit seinen acht Bögen wellen; drei innere Eckpunkte fixiert.</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="49"/>
        <source>A closed torus of size bands of cones, 2 × size strips around: developable strip by strip but not from one sheet; its cutting pattern has one piece per band.</source>
        <translation>Ein geschlossener Torus aus size Bändern von Kegeln, 2 × size Streifen rundherum: Streifen für Streifen abwickelbar, aber nicht aus einem Bogen; sein Schnittmuster hat ein Teil je Band.</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="55"/>
        <source>A pleated column after Huffman&apos;s hexagonal column: a tube folded along size upright creases with the curved-fold condition, three bottom vertices pinned. It keeps its development around the cylinder it unrolls from. Drag a top vertex up or in.</source>
        <translation>Eine gefaltete Säule nach Huffmans sechseckiger Säule: ein Rohr, entlang size aufrechter Falten mit der Bedingung der gekrümmten Faltung gefaltet, drei untere Eckpunkte fixiert. Sie behält ihre Abwicklung um den Zylinder, von dem sie sich abrollt. Ziehen Sie einen oberen Eckpunkt nach oben oder nach innen.</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="61"/>
        <source>A strip, a pointed strip, a cone and a planar patch; size intervals per curve.</source>
        <translation>Ein Streifen, ein spitzer Streifen, ein Kegel und ein ebenes Flächenstück; Größe Intervalle je Kurve.</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="68"/>
        <source>A flat square of size × size strips with curved creases carrying the curved-fold condition, holding its square sheet with the creases where they lie in it, its bottom-left corner pinned. Select the four middle vertices and drag them up (Drag tool, G) to fold it.</source>
        <translation>Ein ebenes Quadrat aus size × size Streifen mit gekrümmten Falzen, die die Bedingung des gekrümmten Falzes tragen; es hält seinen quadratischen Bogen fest, die Falze dort, wo sie darin liegen, seine linke untere Ecke gepinnt. Wählen Sie die vier mittleren Eckpunkte und ziehen Sie sie nach oben (Ziehwerkzeug, G), um es zu falten.</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="76"/>
        <source>Two strips joined by one curved crease with the curved-fold condition, holding its rectangular sheet with the crease where it lies in it, its bottom-left corner pinned; size intervals per curve. Select both top corners and drag them up and in towards the crease to fold it.</source>
        <translation>Zwei Streifen, verbunden durch einen gekrümmten Falz mit der Bedingung des gekrümmten Falzes; sie halten ihren rechteckigen Bogen fest, der Falz dort, wo er darin liegt, die linke untere Ecke gepinnt; size Intervalle je Kurve. Wählen Sie beide oberen Ecken und ziehen Sie sie nach oben und zum Falz hin, um es zu falten.</translation>
    </message>
</context>
<context>
    <name>FaceType</name>
    <message>
        <location filename="../app/text/face_type_text.cpp" line="10"/>
        <source>strip (SRSR)</source>
        <translation>Streifen (SRSR)</translation>
    </message>
    <message>
        <location filename="../app/text/face_type_text.cpp" line="12"/>
        <source>pointed strip (SRS)</source>
        <translation>spitzer Streifen (SRS)</translation>
    </message>
    <message>
        <location filename="../app/text/face_type_text.cpp" line="14"/>
        <source>cone (SRR)</source>
        <translation>Kegel (SRR)</translation>
    </message>
    <message>
        <location filename="../app/text/face_type_text.cpp" line="16"/>
        <source>planar patch</source>
        <translation>ebenes Flächenstück</translation>
    </message>
    <message>
        <location filename="../app/text/face_type_text.cpp" line="20"/>
        <source>invalid labelling</source>
        <translation>ungültige Beschriftung</translation>
    </message>
</context>
<context>
    <name>JoinSurfacesCommand</name>
    <message>
        <location filename="../model/document/commands/join_surfaces_command.cpp" line="27"/>
        <source>Choose at least two surfaces of the design to join.</source>
        <translation>Wählen Sie mindestens zwei Flächen des Entwurfs zum Verbinden.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/join_surfaces_command.cpp" line="31"/>
        <source>The joined surface is not valid.</source>
        <translation>Die verbundene Fläche ist nicht gültig.</translation>
    </message>
</context>
<context>
    <name>LanguageMenu</name>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="30"/>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="31"/>
        <source>The interface will use this language from the next start of DevSurf.</source>
        <translation>Die Oberfläche verwendet diese Sprache ab dem nächsten Start von DevSurf.</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="37"/>
        <source>&amp;Restart Now</source>
        <translation>Jetzt &amp;neu starten</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="40"/>
        <source>Save your changes and restart DevSurf to use it now.</source>
        <translation>Speichern Sie Ihre Änderungen und starten Sie DevSurf neu, um sie jetzt zu verwenden.</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="42"/>
        <source>&amp;Later</source>
        <translation>&amp;Später</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="42"/>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="60"/>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="68"/>
        <source>&amp;System Language</source>
        <translation>Sprache des &amp;Systems</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="69"/>
        <source>&amp;English</source>
        <translation>&amp;Englisch (English)</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="70"/>
        <source>&amp;German (Deutsch)</source>
        <translation>&amp;Deutsch</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="71"/>
        <source>&amp;Japanese (日本語)</source>
        <translation>&amp;Japanisch (日本語)</translation>
    </message>
</context>
<context>
    <name>MergeStripsCommand</name>
    <message>
        <location filename="../model/document/commands/merge_strips_command.cpp" line="9"/>
        <source>Remove ruling %1</source>
        <translation>Erzeugende %1 entfernen</translation>
    </message>
    <message>
        <location filename="../model/document/commands/merge_strips_command.cpp" line="11"/>
        <source>Ruling %1 cannot be removed</source>
        <translation>Erzeugende %1 kann nicht entfernt werden</translation>
    </message>
</context>
<context>
    <name>MoveVerticesCommand</name>
    <message>
        <location filename="../model/document/commands/move_vertices_command.cpp" line="20"/>
        <source>The vertices cannot be moved by an offset that is not a finite number.</source>
        <translation>Die Ecken können nicht um einen Versatz verschoben werden, der keine endliche Zahl ist.</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/move_vertices_command.cpp" line="23"/>
        <source>Move %n vertices</source>
        <translation>
            <numerusform>%n Ecke verschieben</numerusform>
            <numerusform>%n Ecken verschieben</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/document/commands/move_vertices_command.cpp" line="36"/>
        <source>The vertices cannot be rotated</source>
        <translation>Die Ecken können nicht gedreht werden</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/move_vertices_command.cpp" line="38"/>
        <source>Rotate %n vertices</source>
        <translation>
            <numerusform>%n Ecke drehen</numerusform>
            <numerusform>%n Ecken drehen</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/document/commands/move_vertices_command.cpp" line="46"/>
        <source>The vertices cannot be moved</source>
        <translation>Die Ecken können nicht verschoben werden</translation>
    </message>
</context>
<context>
    <name>OutputProblem</name>
    <message>
        <location filename="../app/gui/output_problem_text.cpp" line="16"/>
        <source>“%1” is the project file of this design: exporting over it would destroy the design. Choose another file name.</source>
        <translation>„%1“ ist die Projektdatei dieses Entwurfs: Ein Export darüber würde den Entwurf zerstören. Wählen Sie einen anderen Dateinamen.</translation>
    </message>
    <message>
        <location filename="../app/gui/output_problem_text.cpp" line="21"/>
        <source>“%1” is a folder. Choose a file name.</source>
        <translation>„%1“ ist ein Ordner. Wählen Sie einen Dateinamen.</translation>
    </message>
    <message>
        <location filename="../app/gui/output_problem_text.cpp" line="24"/>
        <source>“%1” is a device, pipe or socket, not a file. Choose a file name.</source>
        <translation>„%1“ ist ein Gerät, eine Pipe oder ein Socket, keine Datei. Wählen Sie einen Dateinamen.</translation>
    </message>
    <message>
        <location filename="../app/gui/output_problem_text.cpp" line="43"/>
        <source>There is not enough memory to open “%1”.</source>
        <translation>Es ist nicht genug Speicher vorhanden, um „%1“ zu öffnen.</translation>
    </message>
</context>
<context>
    <name>PinVerticesCommand</name>
    <message>
        <location filename="../model/document/commands/pin_vertices_command.cpp" line="9"/>
        <source>Select at least one vertex to pin.</source>
        <translation>Wählen Sie mindestens eine Ecke zum Festhalten aus.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/pin_vertices_command.cpp" line="10"/>
        <source>Select at least one vertex to unpin.</source>
        <translation>Wählen Sie mindestens eine Ecke zum Lösen aus.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/pin_vertices_command.cpp" line="20"/>
        <source>Vertex %1 does not exist.</source>
        <translation>Ecke %1 gibt es nicht.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/pin_vertices_command.cpp" line="25"/>
        <source>The selected vertices are already pinned.</source>
        <translation>Die ausgewählten Ecken sind bereits festgehalten.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/pin_vertices_command.cpp" line="26"/>
        <source>The selected vertices are not pinned.</source>
        <translation>Die ausgewählten Ecken sind nicht festgehalten.</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/pin_vertices_command.cpp" line="29"/>
        <source>Pin %n vertices</source>
        <translation>
            <numerusform>%n Ecke festhalten</numerusform>
            <numerusform>%n Ecken festhalten</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/pin_vertices_command.cpp" line="29"/>
        <source>Unpin %n vertices</source>
        <translation>
            <numerusform>%n Ecke freigeben</numerusform>
            <numerusform>%n Ecken freigeben</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ProblemText</name>
    <message>
        <location filename="../app/text/problem_text.cpp" line="39"/>
        <source>no patch</source>
        <translation>keinem Flächenstück</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="42"/>
        <source>patch %1</source>
        <translation>Flächenstück %1</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="44"/>
        <source>patches %1</source>
        <translation>Flächenstücke %1</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="49"/>
        <source>degree %1, C%2, 1 interval</source>
        <translation>Grad %1, C%2, 1 Intervall</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="51"/>
        <source>degree %1, C%2, %3 intervals</source>
        <translation>Grad %1, C%2, %3 Intervalle</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="59"/>
        <source>Surface %1</source>
        <translation>Fläche %1</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="61"/>
        <source>Surface %1 “%2”</source>
        <translation>Fläche %1 „%2“</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="68"/>
        <source>The surface has no patches.</source>
        <translation>Die Fläche hat keine Flächenstücke.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="70"/>
        <source>Vertex id %1 is used twice.</source>
        <translation>Die Ecken-ID %1 wird zweimal verwendet.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="71"/>
        <source>Edge id %1 is used twice.</source>
        <translation>Die Kanten-ID %1 wird zweimal verwendet.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="72"/>
        <source>Patch id %1 is used twice.</source>
        <translation>Die Flächenstück-ID %1 wird zweimal verwendet.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="74"/>
        <source>Vertex %1 does not exist.</source>
        <translation>Ecke %1 gibt es nicht.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="75"/>
        <source>Edge %1 does not exist.</source>
        <translation>Kante %1 gibt es nicht.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="76"/>
        <source>Patch %1 does not exist.</source>
        <translation>Flächenstück %1 gibt es nicht.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="78"/>
        <source>Edge %1 does not join two distinct existing vertices.</source>
        <translation>Kante %1 verbindet nicht zwei verschiedene vorhandene Ecken.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="80"/>
        <source>Edge %1 duplicates the edge between vertices %2 and %3.</source>
        <translation>Kante %1 doppelt die Kante zwischen den Ecken %2 und %3.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="85"/>
        <source>Patch %1 has fewer than three corners.</source>
        <translation>Flächenstück %1 hat weniger als drei Ecken.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="87"/>
        <source>Patch %1 visits a vertex twice.</source>
        <translation>Flächenstück %1 durchläuft eine Ecke zweimal.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="89"/>
        <source>Patch %1 refers to vertex %2, which does not exist.</source>
        <translation>Flächenstück %1 verweist auf Ecke %2, die es nicht gibt.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="91"/>
        <source>Patch %1 runs along the edge from vertex %2 to vertex %3 in the same direction as another patch: patches must be oriented consistently and an edge can border at most two patches.</source>
        <translation>Flächenstück %1 läuft entlang der Kante von Ecke %2 zu Ecke %3 in derselben Richtung wie ein anderes Flächenstück: Flächenstücke müssen einheitlich orientiert sein, und eine Kante kann höchstens zwei Flächenstücke begrenzen.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="98"/>
        <source>Patch %1 cannot be attached without making the surface non-manifold.</source>
        <translation>Flächenstück %1 kann nicht angefügt werden, ohne dass die Fläche nicht-mannigfaltig wird.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="101"/>
        <source>There is no edge between vertices %1 and %2.</source>
        <translation>Zwischen den Ecken %1 und %2 gibt es keine Kante.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="103"/>
        <source>Edge %1 is a curve; only rulings are smooth or sharp.</source>
        <translation>Kante %1 ist eine Kurve; nur Erzeugende sind glatt oder scharf.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="105"/>
        <source>Vertex %1 belongs to no patch.</source>
        <translation>Ecke %1 gehört zu keinem Flächenstück.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="106"/>
        <source>Edge %1 belongs to no patch.</source>
        <translation>Kante %1 gehört zu keinem Flächenstück.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="108"/>
        <source>Vertex %1 lies beyond the id counter.</source>
        <translation>Ecke %1 liegt jenseits des ID-Zählers.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="109"/>
        <source>Edge %1 lies beyond the id counter.</source>
        <translation>Kante %1 liegt jenseits des ID-Zählers.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="110"/>
        <source>Patch %1 lies beyond the id counter.</source>
        <translation>Flächenstück %1 liegt jenseits des ID-Zählers.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="112"/>
        <source>Edge %1 is a ruling but carries spline data.</source>
        <translation>Kante %1 ist eine Erzeugende, trägt aber Splinedaten.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="114"/>
        <source>Edge %1 is marked smooth but is not shared by two patches.</source>
        <translation>Kante %1 ist als glatt markiert, gehört aber nicht zu zwei Flächenstücken.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="116"/>
        <source>Edge %1 is a curve but is marked smooth (only rulings are).</source>
        <translation>Kante %1 ist eine Kurve, ist aber als glatt markiert (das können nur Erzeugende sein).</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="118"/>
        <source>Edge %1 has an invalid spline space (%2).</source>
        <translation>Kante %1 hat einen ungültigen Splineraum (%2).</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="122"/>
        <source>Edge %1 has %2 control points; its spline space (%3) needs %4.</source>
        <translation>Kante %1 hat %2 Kontrollpunkte; ihr Splineraum (%3) braucht %4.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="128"/>
        <source>Edge %1 has a control point that is not a finite number.</source>
        <translation>Kante %1 hat einen Kontrollpunkt, der keine endliche Zahl ist.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="131"/>
        <source>Edge %1 does not start at its vertex %2.</source>
        <translation>Kante %1 beginnt nicht an ihrer Ecke %2.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="132"/>
        <source>Edge %1 does not end at its vertex %2.</source>
        <translation>Kante %1 endet nicht an ihrer Ecke %2.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="134"/>
        <source>Edge %1 carries a crease condition but is not shared by two patches.</source>
        <translation>Kante %1 trägt eine Falzbedingung, gehört aber nicht zu zwei Flächenstücken.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="137"/>
        <source>Patch %1 is labelled %2; a patch must be an SRSR strip, an SRS strip, an SRR cone or a polygon of rulings only (R…R).</source>
        <translation>Flächenstück %1 ist mit %2 beschriftet; ein Flächenstück muss ein SRSR-Streifen, ein SRS-Streifen, ein SRR-Kegel oder ein Polygon nur aus Erzeugenden (R…R) sein.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="142"/>
        <source>Curves %1 and %2 are connected through patches but use different spline spaces (%3 and %4).</source>
        <translation>Die Kurven %1 und %2 sind über Flächenstücke verbunden, haben aber verschiedene Splineräume (%3 und %4).</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="148"/>
        <source>The kept development has %1 points, but the surface&apos;s sampled mesh has %2.</source>
        <translation>Die beibehaltene Abwicklung hat %1 Punkte, das abgetastete Netz der Fläche aber %2.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="152"/>
        <source>A point of the kept development is not a finite number.</source>
        <translation>Ein Punkt der beibehaltenen Abwicklung ist keine endliche Zahl.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="155"/>
        <source>The sheet&apos;s inner radius must be smaller than its outer radius.</source>
        <translation>Der Innenradius des Bogens muss kleiner als sein Außenradius sein.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="158"/>
        <source>The sheet&apos;s outline has no closed loop enclosing an area.</source>
        <translation>Der Umriss des Bogens hat keine geschlossene Kontur, die eine Fläche umschließt.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="161"/>
        <source>A crease curve of the sheet has too few points, a point that is not a finite number, or is not there.</source>
        <translation>Eine Falzkurve des Bogens hat zu wenige Punkte, einen Punkt, der keine endliche Zahl ist, oder fehlt.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="164"/>
        <source>The sheet&apos;s sizes must be finite and greater than zero.</source>
        <translation>Die Maße des Bogens müssen endlich und größer als null sein.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="166"/>
        <source>Vertex %1 (of %2) has a position that is not a finite number.</source>
        <translation>Ecke %1 (von %2) hat eine Lage, die keine endliche Zahl ist.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="170"/>
        <source>Vertex %1 (of %2) lies %3 mm from the origin; coordinates beyond %4 mm (1 km) are not accepted.</source>
        <translation>Ecke %1 (von %2) liegt %3 mm vom Ursprung entfernt; Koordinaten jenseits von %4 mm (1 km) werden nicht angenommen.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="175"/>
        <source>Edge %1 (a curve of %2) has a control point beyond %3 mm from the origin.</source>
        <translation>Kante %1 (eine Kurve von %2) hat einen Kontrollpunkt weiter als %3 mm vom Ursprung.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="179"/>
        <source>Edge %1 (a curve of %2) has zero length.</source>
        <translation>Kante %1 (eine Kurve von %2) hat die Länge null.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="181"/>
        <source>Edge %1 (a curve of %2) is pinched: a stretch of it has shrunk to a point.</source>
        <translation>Kante %1 (eine Kurve von %2) ist eingeschnürt: ein Stück von ihr ist auf einen Punkt geschrumpft.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="185"/>
        <source>Edge %1 (a ruling of %2) has zero length.</source>
        <translation>Kante %1 (eine Erzeugende von %2) hat die Länge null.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="187"/>
        <source>Patch %1 has coincident vertices %2 and %3.</source>
        <translation>Flächenstück %1 hat zusammenfallende Ecken %2 und %3.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="192"/>
        <source>Patch %1 has zero area.</source>
        <translation>Flächenstück %1 hat den Flächeninhalt null.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="194"/>
        <source>Patch %1 is a %2; only an SRSR strip can be cut by a new crease.</source>
        <translation>Flächenstück %1 ist vom Typ „%2“; nur ein SRSR-Streifen kann durch einen neuen Falz geteilt werden.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="198"/>
        <source>The new crease cannot continue across ruling edge %1 into patch %2, a %3; a row of strips can only be cut where its rulings border SRSR strips, planar patches or the boundary.</source>
        <translation>Der neue Falz kann nicht über die Erzeugende %1 in das Flächenstück %2 (Typ „%3“) weiterlaufen; eine Reihe von Streifen kann nur geteilt werden, wo ihre Erzeugenden an SRSR-Streifen, ebene Flächenstücke oder den Rand grenzen.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="205"/>
        <source>The row of strips through patch %1 closes on itself with its sides swapped, so it cannot be cut at one distance between its curves.</source>
        <translation>Die Reihe von Streifen durch Flächenstück %1 schließt sich mit vertauschten Seiten, daher kann sie nicht in einem Abstand zwischen ihren Kurven geteilt werden.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="209"/>
        <source>The new crease must lie strictly between the strip&apos;s two curves (0 &lt; t &lt; 1, not %1).</source>
        <translation>Der neue Falz muss echt zwischen den beiden Kurven des Streifens liegen (0 &lt; t &lt; 1, nicht %1).</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="213"/>
        <source>No edge was given to relabel.</source>
        <translation>Es wurde keine Kante angegeben, deren Kennzeichnung (R/S) geändert werden soll.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="215"/>
        <source>Edge %1 is not a spline curve.</source>
        <translation>Kante %1 ist keine Splinekurve.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="217"/>
        <source>Patch %1 is a %2; a ruling can only be added to a strip or a cone.</source>
        <translation>Flächenstück %1 ist vom Typ „%2“; eine Erzeugende kann nur einem Streifen oder Kegel hinzugefügt werden.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="221"/>
        <source>The curves of patch %1 have a single interval; refine them before adding a ruling.</source>
        <translation>Die Kurven von Flächenstück %1 haben nur ein Intervall; verfeinern Sie sie, bevor Sie eine Erzeugende hinzufügen.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="225"/>
        <source>A ruling can only be added at an interior breakpoint i/%1 of the curves of patch %2 (1 ≤ i ≤ %3, not %4); refine the curves for finer positions.</source>
        <translation>Eine Erzeugende kann nur an einem inneren Knoten i/%1 der Kurven von Flächenstück %2 hinzugefügt werden (1 ≤ i ≤ %3, nicht %4); verfeinern Sie die Kurven für feinere Positionen.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="232"/>
        <source>The curves connected to patch %1 meet themselves reversed, so no ruling position is consistent across them.</source>
        <translation>Die mit Flächenstück %1 verbundenen Kurven treffen sich selbst umgekehrt, daher passt keine Position einer Erzeugenden zu allen.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="236"/>
        <source>Curve %1 uses a different spline space from the curves of patch %2.</source>
        <translation>Kurve %1 hat einen anderen Splineraum als die Kurven von Flächenstück %2.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="240"/>
        <source>Refining needs a factor of at least 2, not %1.</source>
        <translation>Das Verfeinern braucht einen Faktor von mindestens 2, nicht %1.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="242"/>
        <source>The curves of edge %1 already have %2 intervals; refining them beyond %3 is not supported.</source>
        <translation>Die Kurven von Kante %1 haben schon %2 Intervalle; mehr als %3 werden nicht unterstützt.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="248"/>
        <source>No vertex was given to move.</source>
        <translation>Es wurde keine Ecke zum Verschieben angegeben.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="250"/>
        <source>A rotation needs a finite axis point, a non-zero axis direction and a finite angle.</source>
        <translation>Eine Drehung braucht einen endlichen Achsenpunkt, eine Achsenrichtung ungleich null und einen endlichen Winkel.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="257"/>
        <source>There is no example called “%1”; the examples are %2.</source>
        <translation>Es gibt kein Beispiel namens „%1“; die Beispiele sind %2.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="261"/>
        <source>The size of the example “%1” must be between %2 and %3, not %4.</source>
        <translation>Die Größe des Beispiels „%1“ muss zwischen %2 und %3 liegen, nicht %4.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="267"/>
        <source>The number of samples per spline interval must be between 1 and %1, not %2.</source>
        <translation>Die Zahl der Abtastpunkte je Splineintervall muss zwischen 1 und %1 liegen, nicht %2.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="271"/>
        <source>Patch %1 is not a strip or a cone.</source>
        <translation>Flächenstück %1 ist weder ein Streifen noch ein Kegel.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="273"/>
        <source>The two shapes do not have the same patches.</source>
        <translation>Die beiden Formen haben nicht dieselben Flächenstücke.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="275"/>
        <source>Edge %1 has a crease condition but is a boundary curve, not a crease.</source>
        <translation>Kante %1 hat eine Falzbedingung, ist aber eine Randkurve, kein Falz.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="278"/>
        <source>Edge %1 has a crease condition but a cone or planar patch lies beside it; crease conditions need a strip on either side.</source>
        <translation>Kante %1 hat eine Falzbedingung, aber neben ihr liegt ein Kegel oder ein ebenes Flächenstück; Falzbedingungen brauchen auf beiden Seiten einen Streifen.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="283"/>
        <source>Edge %1 has a crease condition but its curve is of degree %2; a crease condition needs degree 2 or more.</source>
        <translation>Kante %1 hat eine Falzbedingung, aber ihre Kurve hat den Grad %2; eine Falzbedingung braucht Grad 2 oder mehr.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/text/problem_text.cpp" line="289"/>
        <source>The surface is not one sheet: it has %n separate part(s).</source>
        <translation>
            <numerusform>Die Fläche ist kein einzelner Bogen: sie hat %n getrennten Teil.</numerusform>
            <numerusform>Die Fläche ist kein einzelner Bogen: sie hat %n getrennte Teile.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="292"/>
        <source>The surface is not one flat sheet: its unfolding misses closing up by %1 mm.</source>
        <translation>Die Fläche ist kein einzelner ebener Bogen: ihre Abwicklung schließt sich um %1 mm nicht.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="295"/>
        <source>Edge %1 cannot be welded: a weld joins two boundary edges of the same kind (two curves or two rulings) of two different patches.</source>
        <translation>Kante %1 kann nicht verschweißt werden: eine Verschweißung verbindet zwei Randkanten derselben Art (zwei Kurven oder zwei Erzeugende) zweier verschiedener Flächenstücke.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="299"/>
        <source>Edges %1 and %2 lie up to %3 mm apart, more than the %4 mm within which they can be welded.</source>
        <translation>Die Kanten %1 und %2 liegen bis zu %3 mm auseinander, mehr als die %4 mm, innerhalb derer sie verschweißt werden können.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="305"/>
        <source>The strips beside edge %1 cannot be merged: it must be a ruling between two strips whose curves are boundary curves of the same degree and smoothness, and its ends may belong to no other patch.</source>
        <translation>Die Streifen neben Kante %1 können nicht zusammengeführt werden: sie muss eine Erzeugende zwischen zwei Streifen sein, deren Kurven Randkurven desselben Grades und derselben Glattheit sind, und ihre Enden dürfen zu keinem anderen Flächenstück gehören.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="312"/>
        <source>DevSurf met an internal error (%1). Please report it.</source>
        <translation>DevSurf ist auf einen internen Fehler gestoßen (%1). Bitte melden Sie ihn.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="330"/>
        <source>The sheet size must be positive; the pieces are laid out side by side.</source>
        <translation>Die Bogengröße muss positiv sein; die Teile werden nebeneinander gelegt.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="332"/>
        <source>%1 is not valid and has no pattern: %2</source>
        <translation>%1 ist ungültig und hat kein Schnittmuster: %2</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="335"/>
        <source>%1 could not be developed: %2</source>
        <translation>%1 konnte nicht abgewickelt werden: %2</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="338"/>
        <source>Piece %1 (%2) overlaps itself at patches %3 and cannot be cut from one sheet.</source>
        <translation>Teil %1 (%2) überlappt sich selbst bei den Flächenstücken %3 und kann nicht aus einem Bogen geschnitten werden.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="341"/>
        <source>Pieces %1 (patches %2) and %3 (patches %4) overlap on sheet %5.</source>
        <translation>Die Teile %1 (Flächenstücke %2) und %3 (Flächenstücke %4) überlappen sich auf Bogen %5.</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="346"/>
        <source>Piece %1 (%2) measures %3 × %4 mm and does not fit on the %5 × %6 mm sheet with a %7 mm gap.</source>
        <translation>Teil %1 (%2) misst %3 × %4 mm und passt mit %7 mm Abstand nicht auf den Bogen von %5 × %6 mm.</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="35"/>
        <source>Laser bed 600 × 400 mm</source>
        <translation>Laserbett 600 × 400 mm</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="36"/>
        <source>A4 (210 × 297 mm)</source>
        <translation>A4 (210 × 297 mm)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="37"/>
        <source>A3 (297 × 420 mm)</source>
        <translation>A3 (297 × 420 mm)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="38"/>
        <source>Letter (8.5 × 11 in)</source>
        <translation>Letter (8,5 × 11 in)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="39"/>
        <source>Custom</source>
        <translation>Benutzerdefiniert</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="36"/>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="44"/>
        <source>Nothing to print</source>
        <translation>Nichts zu drucken</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="46"/>
        <source>The design has no surface to develop.</source>
        <translation>Der Entwurf hat keine Fläche, die abgewickelt werden kann.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="62"/>
        <source>Printing the cutting pattern…</source>
        <translation>Der Schnittmusterplan wird gedruckt…</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="62"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="152"/>
        <source>Export &amp;Cutting Pattern…</source>
        <translation>&amp;Schnittmuster exportieren…</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="154"/>
        <source>&amp;Print…</source>
        <translation>&amp;Drucken…</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="157"/>
        <source>Print Pre&amp;view…</source>
        <translation>Druck&amp;vorschau…</translation>
    </message>
</context>
<context>
    <name>ReferenceCurvesCommand</name>
    <message>
        <location filename="../model/document/commands/reference_curves_command.cpp" line="31"/>
        <source>There are no curves to import.</source>
        <translation>Es gibt keine Kurven zum Importieren.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/reference_curves_command.cpp" line="35"/>
        <source>A curve to import has fewer than two points or a coordinate that is not a number.</source>
        <translation>Eine zu importierende Kurve hat weniger als zwei Punkte oder eine Koordinate, die keine Zahl ist.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/reference_curves_command.cpp" line="44"/>
        <source>Import Curves</source>
        <translation>Kurven importieren</translation>
    </message>
    <message>
        <location filename="../model/document/commands/reference_curves_command.cpp" line="51"/>
        <source>Select at least one reference curve to remove.</source>
        <translation>Wählen Sie mindestens eine Referenzkurve zum Entfernen.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/reference_curves_command.cpp" line="55"/>
        <source>Reference curve %1 does not exist.</source>
        <translation>Die Referenzkurve %1 gibt es nicht.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/reference_curves_command.cpp" line="65"/>
        <source>Remove Reference Curves</source>
        <translation>Referenzkurven entfernen</translation>
    </message>
    <message>
        <location filename="../model/document/commands/reference_curves_command.cpp" line="71"/>
        <source>The design has no reference curves.</source>
        <translation>Der Entwurf hat keine Referenzkurven.</translation>
    </message>
</context>
<context>
    <name>ReferenceShapesCommand</name>
    <message>
        <location filename="../model/document/commands/reference_shapes_command.cpp" line="39"/>
        <source>The shape to import has no points, a coordinate that is not a number or a triangle naming a point it does not have.</source>
        <translation>Die zu importierende Form hat keine Punkte, eine Koordinate, die keine Zahl ist, oder ein Dreieck, das einen Punkt nennt, den sie nicht hat.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/reference_shapes_command.cpp" line="45"/>
        <source>Import Reference Shape</source>
        <translation>Referenzform importieren</translation>
    </message>
    <message>
        <location filename="../model/document/commands/reference_shapes_command.cpp" line="50"/>
        <source>The design has no reference shapes.</source>
        <translation>Der Entwurf hat keine Referenzformen.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/reference_shapes_command.cpp" line="53"/>
        <source>Remove Reference Shapes</source>
        <translation>Referenzformen entfernen</translation>
    </message>
</context>
<context>
    <name>RefineSplineClassCommand</name>
    <message>
        <location filename="../model/document/commands/refine_spline_class_command.cpp" line="9"/>
        <source>Refine curves</source>
        <translation>Kurven verfeinern</translation>
    </message>
    <message>
        <location filename="../model/document/commands/refine_spline_class_command.cpp" line="11"/>
        <source>The curves of edge %1 cannot be refined</source>
        <translation>Die Kurven der Kante %1 können nicht verfeinert werden</translation>
    </message>
</context>
<context>
    <name>RelabelEdgeCommand</name>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="16"/>
        <source>Select at least one edge to relabel.</source>
        <translation>Wählen Sie mindestens eine Kante aus, deren Kennzeichnung (R/S) geändert werden soll.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="23"/>
        <source>Make edge %1 a spline curve</source>
        <translation>Kante %1 zur Splinekurve machen</translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="24"/>
        <source>Make edge %1 a ruling</source>
        <translation>Kante %1 zur Erzeugenden machen</translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="25"/>
        <source>Edge %1 cannot become a spline curve</source>
        <translation>Kante %1 kann keine Splinekurve werden</translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="26"/>
        <source>Edge %1 cannot become a ruling</source>
        <translation>Kante %1 kann keine Erzeugende werden</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="28"/>
        <source>Relabel %n edges</source>
        <translation>
            <numerusform>Kennzeichnung von %n Kante ändern</numerusform>
            <numerusform>Kennzeichnung von %n Kanten ändern</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="29"/>
        <source>The edges cannot be relabelled</source>
        <translation>Die Kennzeichnung der Kanten kann nicht geändert werden</translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="39"/>
        <source>Edge %1 is already a spline curve.</source>
        <translation>Kante %1 ist bereits eine Splinekurve.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="40"/>
        <source>Edge %1 is already a ruling.</source>
        <translation>Kante %1 ist bereits eine Erzeugende.</translation>
    </message>
</context>
<context>
    <name>SceneView</name>
    <message>
        <location filename="../views/quality_colours.cpp" line="81"/>
        <source>developable</source>
        <translation>abwickelbar</translation>
    </message>
    <message>
        <location filename="../views/quality_colours.cpp" line="98"/>
        <source>Developability
|det(a-b, a&apos;, b&apos;)|
(ratio)</source>
        <translation>Abwickelbarkeit
|det(a-b, a&apos;, b&apos;)|
(Verhältnis)</translation>
    </message>
    <message>
        <location filename="../views/quality_colours.cpp" line="101"/>
        <source>Flatness δ
(ratio)</source>
        <translation>Ebenheit δ
(Verhältnis)</translation>
    </message>
    <message>
        <location filename="../views/quality_colours.cpp" line="103"/>
        <source>Angle defect |K|
(rad)</source>
        <translation>Winkeldefekt |K|
(rad)</translation>
    </message>
    <message>
        <location filename="../views/distance_legend.cpp" line="84"/>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
</context>
<context>
    <name>SheetText</name>
    <message>
        <location filename="../app/text/sheet_text.cpp" line="6"/>
        <source>the pinned vertices %1 and %2 are as far apart as along the straight line between them in the sheet, so that line stays straight and the strips it lies on stay flat, and a curved crease beside a flat strip cannot fold (unpin one of them to let the sheet fold)</source>
        <translation>die fixierten Eckpunkte %1 und %2 liegen so weit auseinander wie entlang der geraden Linie zwischen ihnen im Bogen, daher bleibt diese Linie gerade und die Streifen, auf denen sie liegt, bleiben eben, und ein gekrümmter Falz neben einem ebenen Streifen kann nicht falten (lösen Sie einen der beiden, damit sich der Bogen falten kann)</translation>
    </message>
</context>
<context>
    <name>SmoothRulingsCommand</name>
    <message>
        <location filename="../model/document/commands/smooth_rulings_command.cpp" line="9"/>
        <source>Select at least one ruling between two patches.</source>
        <translation>Wählen Sie mindestens eine Erzeugende zwischen zwei Flächenstücken aus.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/smooth_rulings_command.cpp" line="19"/>
        <source>Edge %1 does not exist.</source>
        <translation>Kante %1 existiert nicht.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/smooth_rulings_command.cpp" line="23"/>
        <source>Edge %1 is a curve; only rulings between two patches are smooth or sharp (curves take a crease condition).</source>
        <translation>Kante %1 ist eine Kurve; nur Erzeugende zwischen zwei Flächenstücken sind glatt oder scharf (Kurven erhalten eine Falzbedingung).</translation>
    </message>
    <message>
        <location filename="../model/document/commands/smooth_rulings_command.cpp" line="29"/>
        <source>Edge %1 is a ruling on the boundary; only rulings between two patches are smooth or sharp.</source>
        <translation>Kante %1 ist eine Erzeugende am Rand; nur Erzeugende zwischen zwei Flächenstücken sind glatt oder scharf.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/smooth_rulings_command.cpp" line="36"/>
        <source>The selected rulings are already smooth.</source>
        <translation>Die ausgewählten Erzeugenden sind bereits glatt.</translation>
    </message>
    <message>
        <location filename="../model/document/commands/smooth_rulings_command.cpp" line="37"/>
        <source>The selected rulings are already sharp.</source>
        <translation>Die ausgewählten Erzeugenden sind bereits scharf.</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/smooth_rulings_command.cpp" line="39"/>
        <source>Make %n rulings smooth</source>
        <translation>
            <numerusform>%n Erzeugende glatt machen</numerusform>
            <numerusform>%n Erzeugende glatt machen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/smooth_rulings_command.cpp" line="40"/>
        <source>Make %n rulings sharp</source>
        <translation>
            <numerusform>%n Erzeugende scharf machen</numerusform>
            <numerusform>%n Erzeugende scharf machen</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SplitAtRulingCommand</name>
    <message>
        <location filename="../model/document/commands/split_at_ruling_command.cpp" line="12"/>
        <source>Add a ruling across patch %1</source>
        <translation>Erzeugende quer über Flächenstück %1 einfügen</translation>
    </message>
    <message>
        <location filename="../model/document/commands/split_at_ruling_command.cpp" line="14"/>
        <source>No ruling can be added across patch %1</source>
        <translation>Über Flächenstück %1 kann keine Erzeugende eingefügt werden</translation>
    </message>
</context>
<context>
    <name>SubdivideStripCommand</name>
    <message>
        <location filename="../model/document/commands/subdivide_strip_command.cpp" line="9"/>
        <source>Add a crease across patch %1</source>
        <translation>Falz quer über Flächenstück %1 einfügen</translation>
    </message>
    <message>
        <location filename="../model/document/commands/subdivide_strip_command.cpp" line="11"/>
        <source>No crease can be added across patch %1</source>
        <translation>Über Flächenstück %1 kann kein Falz eingefügt werden</translation>
    </message>
</context>
<context>
    <name>SurfaceEditCommand</name>
    <message>
        <location filename="../model/document/commands/surface_edit_command.cpp" line="50"/>
        <source>There is no surface number %1 in the design.</source>
        <translation>Der Entwurf hat keine Fläche Nummer %1.</translation>
    </message>
</context>
<context>
    <name>VerdictText</name>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="26"/>
        <source>patch %1</source>
        <translation>Flächenstück %1</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="27"/>
        <source>patches %1</source>
        <translation>Flächenstücke %1</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="29"/>
        <source>surface %1 %2</source>
        <translation>Fläche %1 %2</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="38"/>
        <source>undo the last step and make a smaller change</source>
        <translation>den letzten Schritt rückgängig machen und weniger ändern</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="41"/>
        <source>solve with more iterations</source>
        <translation>mit mehr Iterationen lösen</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="44"/>
        <source>release pins that hold the sheet</source>
        <translation>Fixierungen lösen, die den Bogen halten</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="47"/>
        <source>solve again</source>
        <translation>erneut lösen</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="49"/>
        <source>; or </source>
        <translation>; oder </translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="56"/>
        <source>&lt; 0.0001</source>
        <translation>&lt; 0,0001</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="66"/>
        <source>Developable to the tolerance — ready to cut.</source>
        <translation>Abwickelbar innerhalb der Toleranz — bereit zum Zuschnitt.</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="69"/>
        <source>Developable to within %1 mm of isometry over the sheet: the cut pattern is off by at most %1 mm.</source>
        <translation>Abwickelbar bis auf %1 mm Abweichung von der Isometrie über den Bogen: das Schnittmuster weicht höchstens %1 mm ab.</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="76"/>
        <source>Developable patch by patch, but the development overlaps itself at %1: it cannot be cut from one piece. Try: %2.</source>
        <translation>Patch für Patch abwickelbar, aber die Abwicklung überlappt sich bei %1: sie lässt sich nicht aus einem Stück schneiden. Versuchen Sie: %2.</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="81"/>
        <source>Not developable: the surface folds over or its development overlaps itself</source>
        <translation>Nicht abwickelbar: die Fläche faltet sich über sich selbst oder ihre Abwicklung überlappt sich</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="84"/>
        <source>Not developable from its sheet: it lies %1 mm from the sheet it keeps</source>
        <translation>Nicht aus seinem Bogen abwickelbar: die Fläche liegt %1 mm neben dem gehaltenen Bogen</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="86"/>
        <location filename="../app/text/verdict_text.cpp" line="107"/>
        <source>Not developable</source>
        <translation>Nicht abwickelbar</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="87"/>
        <source>%1. Try: %2.</source>
        <translation>%1. Versuchen Sie: %2.</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="88"/>
        <source>%1 at %2. Try: %3.</source>
        <translation>%1 bei %2. Versuchen Sie: %3.</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="99"/>
        <source>Developable — ready to cut</source>
        <translation>Abwickelbar — bereit zum Zuschnitt</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="101"/>
        <source>Developable within %1 mm</source>
        <translation>Abwickelbar auf %1 mm genau</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="105"/>
        <source>Development overlaps itself: %1</source>
        <translation>Abwicklung überlappt sich: %1</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="107"/>
        <source>Not developable: %1</source>
        <translation>Nicht abwickelbar: %1</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="117"/>
        <source>Largest constraint residual %1 (tolerance %2).</source>
        <translation>Größtes Residuum der Bedingungen %1 (Toleranz %2).</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="122"/>
        <source>Development: largest relative edge-length error %1 over a sheet of %2 mm, %3 mm from isometric.</source>
        <translation>Abwicklung: größter relativer Kantenlängenfehler %1 über einen Bogen von %2 mm, %3 mm von der Isometrie entfernt.</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="131"/>
        <source>Distance from the sheet it keeps: %1 mm.</source>
        <translation>Abstand zum gehaltenen Bogen: %1 mm.</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ApproximateDialog</name>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="29"/>
        <source>Approximate Reference Shape</source>
        <translation>Referenzform annähern</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/approximate_dialog.cpp" line="36"/>
        <source>%1 (%n point(s))</source>
        <translation>
            <numerusform>%1 (%n Punkt)</numerusform>
            <numerusform>%1 (%n Punkte)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="40"/>
        <source>Reference &amp;shape:</source>
        <translation>Referenz&amp;form:</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="44"/>
        <source>&amp;New strips:</source>
        <translation>&amp;Neue Streifen:</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="46"/>
        <source>Lay as many flat strips over patches of the shape (k-means clusters; where the shape curves both ways, bands twice as long as wide), pull them towards the shape and add them to the design. A strip that cannot follow the shape and stay developable is pulled again, damped, from the cylinder that fits its points best. Then each is trimmed back where it stands off the shape.</source>
        <translation>Ebenso viele ebene Streifen über Bereiche der Form legen (k-Means-Cluster; wo die Form in beide Richtungen gekrümmt ist, Bänder doppelt so lang wie breit), sie zur Form hin ziehen und dem Entwurf hinzufügen. Ein Streifen, der der Form nicht folgen und abwickelbar bleiben kann, wird erneut gedämpft gezogen, ausgehend von dem Zylinder, der am besten zu seinen Punkten passt. Danach wird jeder Streifen dort zurückgeschnitten, wo er von der Form absteht.</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="56"/>
        <source>As &amp;one surface where the shape allows</source>
        <translation>Als &amp;eine Fläche, wo die Form es zulässt</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="56"/>
        <source>Over a shape seen from one side (a panel), lay the new strips side by side as one watertight surface, bent to the shape, each two sharing a curve along which they may kink; around a shape that closes around an axis (a tube, a vase, a sphere), lay them as rings one after another, one surface open only at its two ends. Off, or over any other shape: separate strips over patches of the shape.</source>
        <translation>Über einer von einer Seite gesehenen Form (einer Platte) die neuen Streifen nebeneinander als eine wasserdichte Fläche legen, an die Form angebogen, je zwei mit einer gemeinsamen Kurve, entlang der sie knicken dürfen; um eine Form, die sich um eine Achse schließt (ein Rohr, eine Vase, eine Kugel), sie als Ringe hintereinander legen, eine Fläche, nur an ihren beiden Enden offen. Aus, oder über jeder anderen Form: getrennte Streifen über Bereiche der Form.</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="56"/>
        <source>The &amp;design&apos;s surfaces</source>
        <translation>Die Flächen des &amp;Entwurfs</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="58"/>
        <source>Pull the surfaces of the design towards the shape; each is pulled by the points nearest to it.</source>
        <translation>Die Flächen des Entwurfs zur Form ziehen; jede wird von den ihr nächsten Punkten gezogen.</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="65"/>
        <source>The design has no surface yet.</source>
        <translation>Der Entwurf hat noch keine Fläche.</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="71"/>
        <source>Start from:</source>
        <translation>Beginnen mit:</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="77"/>
        <source>Spline intervals along each new strip: more follow finer detail and take longer.</source>
        <translation>Spline-Intervalle entlang jedes neuen Streifens: mehr folgen feineren Details und dauern länger.</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="79"/>
        <source>&amp;Intervals per strip:</source>
        <translation>&amp;Intervalle pro Streifen:</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="89"/>
        <source>Iterations of the pull towards the shape; a few more follow in which the pull fades.</source>
        <translation>Iterationen des Zugs zur Form; einige weitere folgen, in denen der Zug abklingt.</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="91"/>
        <source>I&amp;terations:</source>
        <translation>I&amp;terationen:</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="95"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="96"/>
        <source>Thinning radius ρ: the shape is thinned to points at least ρ apart, each with the normal of the points around it.</source>
        <translation>Ausdünnungsradius ρ: die Form wird auf Punkte im Abstand von mindestens ρ ausgedünnt, jeder mit der Normalen der Punkte um ihn.</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="98"/>
        <source>Thinning radius &amp;ρ:</source>
        <translation>Ausdünnungsradius &amp;ρ:</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="107"/>
        <source>&amp;Approximate</source>
        <translation>&amp;Annähern</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="133"/>
        <source>Default: %1 % of the shape&apos;s bounding-box diagonal (%2), or more where its points are sparse.</source>
        <translation>Vorgabe: %1 % der Diagonale des umgebenden Quaders der Form (%2), oder mehr, wo ihre Punkte dünn liegen.</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ApproximateReaction</name>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="50"/>
        <source>Approximate Reference Shape</source>
        <translation>Referenzform annähern</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="88"/>
        <source>Fit developable strips to a reference shape: import one first (File ▸ Import Reference Shape…).</source>
        <translation>Abwickelbare Streifen an eine Referenzform anpassen: zuerst eine importieren (Datei ▸ Referenzform importieren…).</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="90"/>
        <source>Fit developable strips to a reference shape: wait until the solver has finished, or cancel it (Esc).</source>
        <translation>Abwickelbare Streifen an eine Referenzform anpassen: warten, bis der Löser fertig ist, oder ihn abbrechen (Esc).</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="92"/>
        <source>Fit developable strips to a reference shape, or pull the design&apos;s surfaces towards it; one undo step.</source>
        <translation>Abwickelbare Streifen an eine Referenzform anpassen oder die Flächen des Entwurfs zu ihr ziehen; ein Rückgängig-Schritt.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="126"/>
        <source>Preparing the approximation: thinning the reference shape and placing the strips…</source>
        <translation>Annäherung wird vorbereitet: Referenzform ausdünnen und Streifen platzieren…</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="153"/>
        <source>Approximation cancelled; the design is unchanged.</source>
        <translation>Annäherung abgebrochen; der Entwurf ist unverändert.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="168"/>
        <source>Thinning the reference shape with radius %1 kept %n point(s), too few for the strips asked for; choose a smaller radius or fewer strips.</source>
        <translation>
            <numerusform>Das Ausdünnen der Referenzform mit Radius %1 behielt %n Punkt, zu wenige für die gewünschten Streifen; wählen Sie einen kleineren Radius oder weniger Streifen.</numerusform>
            <numerusform>Das Ausdünnen der Referenzform mit Radius %1 behielt %n Punkte, zu wenige für die gewünschten Streifen; wählen Sie einen kleineren Radius oder weniger Streifen.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="174"/>
        <source>The points of the reference shape lie on a line; no strip can be fitted to them.</source>
        <translation>Die Punkte der Referenzform liegen auf einer Geraden; kein Streifen lässt sich an sie anpassen.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="178"/>
        <source>No surface of the design is near enough to the reference shape to be pulled towards it; start from new strips instead.</source>
        <translation>Keine Fläche des Entwurfs liegt nahe genug an der Referenzform, um zu ihr gezogen zu werden; beginnen Sie stattdessen mit neuen Streifen.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="159"/>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="182"/>
        <source>Cannot approximate the reference shape</source>
        <translation>Die Referenzform kann nicht angenähert werden</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="157"/>
        <source>The approximation could not be set up: %1</source>
        <translation>Die Annäherung konnte nicht vorbereitet werden: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="187"/>
        <source>Approximation discarded: the design changed meanwhile; it is unchanged.</source>
        <translation>Annäherung verworfen: der Entwurf hat sich inzwischen geändert; er ist unverändert.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="201"/>
        <source>Measuring the distance of the result to the reference shape…</source>
        <translation>Abstand des Ergebnisses zur Referenzform wird gemessen…</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="238"/>
        <source>%1 failed: %2 The design is unchanged.</source>
        <translation>%1 fehlgeschlagen: %2 Der Entwurf ist unverändert.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="278"/>
        <source>largest constraint residual %1, within the tolerance</source>
        <translation>größtes Bedingungsresiduum %1, innerhalb der Toleranz</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="279"/>
        <source>largest constraint residual %1, not within the tolerance (Tools ▸ Solve may help)</source>
        <translation>größtes Bedingungsresiduum %1, nicht innerhalb der Toleranz (Werkzeuge ▸ Lösen kann helfen)</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="285"/>
        <source>the reference shape is %1 from the %n surface(s) on average, %2 at most</source>
        <translation>
            <numerusform>die Referenzform ist im Mittel %1 von der Fläche entfernt, höchstens %2</numerusform>
            <numerusform>die Referenzform ist im Mittel %1 von den %n Flächen entfernt, höchstens %2</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="289"/>
        <source>Approximated: %1; %2.</source>
        <translation>Angenähert: %1; %2.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="290"/>
        <source>Afterwards %1.</source>
        <translation>Danach: %1.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="292"/>
        <source>Approximated with %n surface(s): %1.</source>
        <translation>
            <numerusform>Mit %n Fläche angenähert: %1.</numerusform>
            <numerusform>Mit %n Flächen angenähert: %1.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="295"/>
        <source>%n surface(s) too far from the shape were left as they were.</source>
        <translation>
            <numerusform>%n Fläche, zu weit von der Form entfernt, blieb unverändert.</numerusform>
            <numerusform>%n Flächen, zu weit von der Form entfernt, blieben unverändert.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="290"/>
        <source>The reference shape closes around an axis: its %n strip(s) were laid as rings one after another around it, one surface open only at its two ends.</source>
        <translation>
            <numerusform>Die Referenzform schließt sich um eine Achse: ihr %n Streifen wurde als Ring um sie gelegt, eine Fläche, nur an ihren beiden Enden offen.</numerusform>
            <numerusform>Die Referenzform schließt sich um eine Achse: ihre %n Streifen wurden als Ringe hintereinander um sie gelegt, eine Fläche, nur an ihren beiden Enden offen.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="290"/>
        <source>The reference shape is one patch: its %n strip(s) were laid side by side as one watertight surface.</source>
        <translation>
            <numerusform>Die Referenzform ist ein einziger Bereich: ihr %n Streifen wurde als eine wasserdichte Fläche gelegt.</numerusform>
            <numerusform>Die Referenzform ist ein einziger Bereich: ihre %n Streifen wurden nebeneinander als eine wasserdichte Fläche gelegt.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="290"/>
        <source>Pulled closer, the surface did not end developable; it was kept as it was laid, bent to the shape.</source>
        <translation>Näher herangezogen wurde die Fläche nicht abwickelbar; sie blieb, wie sie gelegt wurde, an die Form angebogen.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="290"/>
        <source>%n strip(s) were trimmed back where they stood off the shape.</source>
        <translation>
            <numerusform>%n Streifen wurde dort zurückgeschnitten, wo er von der Form abstand.</numerusform>
            <numerusform>%n Streifen wurden dort zurückgeschnitten, wo sie von der Form abstanden.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="290"/>
        <source>%n strip(s) could not be pulled closer and stay developable; they were kept as they were laid.</source>
        <translation>
            <numerusform>%n Streifen ließ sich nicht näher heranziehen, ohne die Abwickelbarkeit zu verlieren; er blieb, wie er gelegt wurde.</numerusform>
            <numerusform>%n Streifen ließen sich nicht näher heranziehen, ohne die Abwickelbarkeit zu verlieren; sie blieben, wie sie gelegt wurden.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="302"/>
        <source>Set up in %1 s, solved in %2 s, measured in %3 s.</source>
        <translation>Vorbereitet in %1 s, gelöst in %2 s, gemessen in %3 s.</translation>
    </message>
</context>
<context>
    <name>devsurf::app::BackgroundRead</name>
    <message>
        <location filename="../app/gui/reactions/background_read.cpp" line="36"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
</context>
<context>
    <name>devsurf::app::CameraActions</name>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="23"/>
        <source>&amp;Reset View</source>
        <translation>Ansicht &amp;zurücksetzen</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="26"/>
        <source>Reset View (Home): the starting direction, the whole design in view</source>
        <translation>Ansicht zurücksetzen (Pos1): die Anfangsrichtung, der ganze Entwurf im Bild</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="31"/>
        <source>&amp;Standard Views</source>
        <translation>&amp;Standardansichten</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="42"/>
        <source>&amp;Isometric</source>
        <translation>&amp;Isometrisch</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="43"/>
        <source>Isometric view (0): from the front right and above</source>
        <translation>Isometrische Ansicht (0): von vorn rechts oben</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="45"/>
        <source>&amp;Front</source>
        <translation>&amp;Vorne</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="45"/>
        <source>Front view (1): looking along +y</source>
        <translation>Vorderansicht (1): Blick entlang +y</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="47"/>
        <source>&amp;Top</source>
        <translation>&amp;Oben</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="47"/>
        <source>Top view (2): looking down along −z</source>
        <translation>Draufsicht (2): Blick nach unten entlang −z</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="49"/>
        <source>&amp;Right</source>
        <translation>&amp;Rechts</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="49"/>
        <source>Right view (3): looking along −x</source>
        <translation>Ansicht von rechts (3): Blick entlang −x</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="51"/>
        <source>R&amp;ear</source>
        <translation>&amp;Hinten</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="51"/>
        <source>Rear view (4): looking along −y</source>
        <translation>Rückansicht (4): Blick entlang −y</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="53"/>
        <source>&amp;Bottom</source>
        <translation>&amp;Unten</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="53"/>
        <source>Bottom view (5): looking up along +z</source>
        <translation>Untersicht (5): Blick nach oben entlang +z</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="55"/>
        <source>&amp;Left</source>
        <translation>&amp;Links</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="55"/>
        <source>Left view (6): looking along +x</source>
        <translation>Ansicht von links (6): Blick entlang +x</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="79"/>
        <source>Patch &amp;Numbers</source>
        <translation>&amp;Nummern der Flächenstücke</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="81"/>
        <source>Ctrl+Shift+N</source>
        <translation>Ctrl+Shift+N</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="82"/>
        <source>Patch Numbers (Ctrl+Shift+N): write each patch&apos;s number on it</source>
        <translation>Nummern der Flächenstücke (Strg+Umschalt+N): jedes Flächenstück mit seiner Nummer beschriften</translation>
    </message>
</context>
<context>
    <name>devsurf::app::CreaseConditionReaction</name>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="70"/>
        <source>Curved fold: the solver keeps the crease&apos;s osculating plane halfway between the two patches, so that the design folds from one flat sheet.</source>
        <translation>Gekrümmte Faltung: Der Löser hält die Schmiegebene des Falzes in der Mitte zwischen den beiden Flächenstücken, damit sich der Entwurf aus einem ebenen Blatt falten lässt.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="74"/>
        <source>Geodesic: the solver keeps the crease a geodesic of both patches.</source>
        <translation>Geodätische: Der Löser hält den Falz als Geodätische beider Flächenstücke.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="77"/>
        <source>Straight when unfolded: the solver keeps the crease a straight line in the development.</source>
        <translation>Gerade in der Abwicklung: Der Löser hält den Falz in der Abwicklung als gerade Linie.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="83"/>
        <source>No condition: the solver treats the crease freely.</source>
        <translation>Keine Bedingung: Der Löser behandelt den Falz frei.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="104"/>
        <source>Select creases (curves between two patches) of one surface first.</source>
        <translation>Wählen Sie zuerst Falze (Kurven zwischen zwei Flächenstücken) einer Fläche.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="163"/>
        <source>Cr&amp;ease</source>
        <translation>&amp;Falz</translation>
    </message>
</context>
<context>
    <name>devsurf::app::DeleteSelectionReaction</name>
    <message>
        <location filename="../app/gui/reactions/edit_reactions.cpp" line="10"/>
        <source>Deleting parts of a surface is not available yet: relabel an edge (Ctrl+L) or undo (Ctrl+Z) instead.</source>
        <translation>Teile einer Fläche zu löschen ist noch nicht möglich: ändern Sie stattdessen die Kennzeichnung einer Kante (Strg+L) oder machen Sie rückgängig (Strg+Z).</translation>
    </message>
</context>
<context>
    <name>devsurf::app::DistanceReportDialog</name>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="26"/>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="31"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="41"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="51"/>
        <source>Mean</source>
        <translation>Mittel</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="52"/>
        <source>95th percentile</source>
        <translation>95. Perzentil</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="53"/>
        <source>Largest</source>
        <translation>Größter</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="54"/>
        <source>Reference shape → design</source>
        <translation>Referenzform → Entwurf</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="55"/>
        <source>Design → reference shape</source>
        <translation>Entwurf → Referenzform</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="82"/>
        <source>Distance to Reference</source>
        <translation>Abstand zur Referenzform</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="149"/>
        <source>The project has no reference shape; import one with File ▸ Import Reference Shape….</source>
        <translation>Das Projekt hat keine Referenzform; importieren Sie eine mit Datei ▸ Referenzform importieren….</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="151"/>
        <location filename="../app/gui/distance_report_dialog.cpp" line="157"/>
        <source>The design has no surface to measure.</source>
        <translation>Der Entwurf hat keine Fläche zum Messen.</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="153"/>
        <source>Measuring the distance between the design and the reference shapes…</source>
        <translation>Der Abstand zwischen Entwurf und Referenzformen wird gemessen…</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="155"/>
        <source>A surface of the design is not valid; solve or undo, then measure again.</source>
        <translation>Eine Fläche des Entwurfs ist ungültig; lösen Sie oder machen Sie rückgängig, dann messen Sie erneut.</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="159"/>
        <source>The design changed: measuring again. The figures below are out of date.</source>
        <translation>Der Entwurf hat sich geändert: Es wird neu gemessen. Die Werte unten sind veraltet.</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="162"/>
        <source>Measured in %1 s.</source>
        <translation>Gemessen in %1 s.</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="186"/>
        <source>Reference shape %1</source>
        <translation>Referenzform %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/distance_report_dialog.cpp" line="193"/>
        <source>Coverage: %1 of the %n point(s) lie within %2 of the design.</source>
        <translation>
            <numerusform>Abdeckung: %1 des %n Punkts liegt innerhalb von %2 am Entwurf.</numerusform>
            <numerusform>Abdeckung: %1 der %n Punkte liegen innerhalb von %2 am Entwurf.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="203"/>
        <source>Two-sided (Hausdorff) distance %1; bounding-box diagonal %2; the design sampled every %3.</source>
        <translation>Beidseitiger (Hausdorff-)Abstand %1; Diagonale des umgebenden Quaders %2; der Entwurf alle %3 abgetastet.</translation>
    </message>
</context>
<context>
    <name>devsurf::app::DistanceReportReaction</name>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="174"/>
        <source>Measure how far the design is from a reference shape: import one first (File ▸ Import Reference Shape…).</source>
        <translation>Misst, wie weit der Entwurf von einer Referenzform entfernt ist: Importieren Sie zuerst eine (Datei ▸ Referenzform importieren…).</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="176"/>
        <source>Measure how far the design is from the reference shapes: the design has no surface yet.</source>
        <translation>Misst, wie weit der Entwurf von den Referenzformen entfernt ist: Der Entwurf hat noch keine Fläche.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="178"/>
        <source>Show how far the design is from each reference shape, both ways (mean, 95th percentile, largest), and how much of the shape it covers.</source>
        <translation>Zeigt, wie weit der Entwurf von jeder Referenzform entfernt ist, in beide Richtungen (Mittel, 95. Perzentil, größter Wert), und wie viel der Form er abdeckt.</translation>
    </message>
</context>
<context>
    <name>devsurf::app::DragTool</name>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="20"/>
        <source>Drag cancelled; the design is as it was.</source>
        <translation>Ziehen abgebrochen; der Entwurf ist wie zuvor.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_text.cpp" line="16"/>
        <source>Drag %n vertices</source>
        <translation>
            <numerusform>%n Ecke ziehen</numerusform>
            <numerusform>%n Ecken ziehen</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_sheet.cpp" line="146"/>
        <source>Drag vertex %1 in the sheet</source>
        <translation>Eckpunkt %1 im Bogen ziehen</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_sheet.cpp" line="148"/>
        <source>Drag %n vertices in the sheet</source>
        <translation>
            <numerusform>%n Eckpunkt im Bogen ziehen</numerusform>
            <numerusform>%n Eckpunkte im Bogen ziehen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_sheet.cpp" line="155"/>
        <source>Dragging %n vertices %1 mm along their sheet; the surface follows. Release to finish, Esc cancels.</source>
        <translation>
            <numerusform>%n Eckpunkt wird %1 mm im Bogen gezogen; die Fläche folgt. Loslassen beendet, Esc bricht ab.</numerusform>
            <numerusform>%n Eckpunkte werden %1 mm im Bogen gezogen; die Fläche folgt. Loslassen beendet, Esc bricht ab.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_sheet.cpp" line="160"/>
        <source>Dragging vertex %1 %2 mm along its sheet; the surface follows. Release to finish, Esc cancels.</source>
        <translation>Eckpunkt %1 wird %2 mm im Bogen gezogen; die Fläche folgt. Loslassen beendet, Esc bricht ab.</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="51"/>
        <source>Sliding crease %1 by %2 mm within the surface, as far as it goes: the patch it moves into keeps %3 % of its width. Release to finish, Esc cancels.</source>
        <translation>Falz %1 wird um %2 mm innerhalb der Fläche verschoben, so weit es geht: das Flächenstück, in das er sich bewegt, behält %3 % seiner Breite. Loslassen beendet, Esc bricht ab.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_text.cpp" line="73"/>
        <source>Dragging %n vertices %1 mm along X. Release to finish, Esc cancels.</source>
        <translation>
            <numerusform>%n Ecke wird %1 mm entlang X gezogen. Loslassen beendet, Esc bricht ab.</numerusform>
            <numerusform>%n Ecken werden %1 mm entlang X gezogen. Loslassen beendet, Esc bricht ab.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_text.cpp" line="76"/>
        <source>Dragging %n vertices %1 mm along Y. Release to finish, Esc cancels.</source>
        <translation>
            <numerusform>%n Ecke wird %1 mm entlang Y gezogen. Loslassen beendet, Esc bricht ab.</numerusform>
            <numerusform>%n Ecken werden %1 mm entlang Y gezogen. Loslassen beendet, Esc bricht ab.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_text.cpp" line="79"/>
        <source>Dragging %n vertices %1 mm along Z. Release to finish, Esc cancels.</source>
        <translation>
            <numerusform>%n Ecke wird %1 mm entlang Z gezogen. Loslassen beendet, Esc bricht ab.</numerusform>
            <numerusform>%n Ecken werden %1 mm entlang Z gezogen. Loslassen beendet, Esc bricht ab.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_text.cpp" line="84"/>
        <source>Dragging %n vertices %1 mm in the view plane. Release to finish, Esc cancels; hold X, Y or Z to move along that axis.</source>
        <translation>
            <numerusform>%n Ecke wird %1 mm in der Bildebene gezogen. Loslassen beendet, Esc bricht ab; X, Y oder Z gedrückt halten bewegt entlang dieser Achse.</numerusform>
            <numerusform>%n Ecken werden %1 mm in der Bildebene gezogen. Loslassen beendet, Esc bricht ab; X, Y oder Z gedrückt halten bewegt entlang dieser Achse.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_sheet.cpp" line="26"/>
        <source>Points of the development can be dragged only where the surface holds its sheet (Tools ▸ Hold the Sheet).</source>
        <translation>Punkte der Abwicklung lassen sich nur ziehen, wo die Fläche ihren Bogen festhält (Werkzeuge ▸ Bogen festhalten).</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool.cpp" line="200"/>
        <source>Vertex %1 is pinned and cannot be dragged; unpin it first.</source>
        <translation>Ecke %1 ist festgehalten und kann nicht gezogen werden; geben Sie sie zuerst frei.</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool.cpp" line="209"/>
        <location filename="../app/gui/drag_tool.cpp" line="252"/>
        <location filename="../app/gui/drag_tool_sheet.cpp" line="51"/>
        <source>a drag started</source>
        <translation>ein Ziehen hat begonnen</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool.cpp" line="235"/>
        <source>There is no edge %1.</source>
        <translation>Es gibt keine Kante %1.</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool.cpp" line="238"/>
        <source>Edge %1 is not a crease (a curve between two patches); only creases can be dragged.</source>
        <translation>Kante %1 ist kein Falz (eine Kurve zwischen zwei Flächenstücken); nur Falze lassen sich ziehen.</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool.cpp" line="243"/>
        <source>Edge %1 cannot move: both its ends are pinned and it has no other control point.</source>
        <translation>Kante %1 kann sich nicht bewegen: beide Enden sind festgehalten und sie hat keinen weiteren Kontrollpunkt.</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool.cpp" line="312"/>
        <source>Snapped to reference curve %1.</source>
        <translation>An Referenzkurve %1 gefangen.</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="96"/>
        <source>Pins %1 and %2 hold vertex %3 on the straight line between them (they are as far apart as in the flat sheet): it moves only by stretching the sheet. </source>
        <translation>Die festgehaltenen Ecken %1 und %2 halten Ecke %3 auf der Geraden zwischen ihnen (sie sind so weit voneinander entfernt wie im flachen Blatt): sie bewegt sich nur, wenn das Blatt gedehnt wird. </translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="102"/>
        <source>Pins %1, %2 and %3 hold vertex %4 in the triangle between them (they are as far apart as in the flat sheet): it moves only by stretching the sheet. </source>
        <translation>Die festgehaltenen Ecken %1, %2 und %3 halten Ecke %4 im Dreieck zwischen ihnen (sie sind so weit voneinander entfernt wie im flachen Blatt): sie bewegt sich nur, wenn das Blatt gedehnt wird. </translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="31"/>
        <source>Drag stopped: %1 The design is as it was.</source>
        <translation>Ziehen beendet: %1 Der Entwurf ist wie zuvor.</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="14"/>
        <source>Drag crease %1</source>
        <translation>Falz %1 ziehen</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="24"/>
        <source>%1: settling, iteration %2 of %3 (Esc cancels).</source>
        <translation>%1: kommt zur Ruhe, Iteration %2 von %3 (Esc bricht ab).</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="35"/>
        <source>Drag tool: press on a vertex in the 3D view and move the mouse; the selected vertices of its surface follow. Press on a crease to slide it within its patches. Esc cancels a drag.</source>
        <translation>Ziehwerkzeug: Drücken Sie in der 3D-Ansicht auf eine Ecke und bewegen Sie die Maus; die ausgewählten Ecken ihrer Fläche folgen. Drücken Sie auf einen Falz, um ihn innerhalb seiner Flächenstücke zu verschieben. Esc bricht das Ziehen ab.</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="41"/>
        <source>Drag stopped: the design changed during the drag.</source>
        <translation>Ziehen beendet: Der Entwurf hat sich während des Ziehens geändert.</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="59"/>
        <source>Sliding crease %1 by %2 mm within the surface. Release to finish, Esc cancels; hold X, Y or Z to move along that axis.</source>
        <translation>Falz %1 wird um %2 mm innerhalb der Fläche verschoben. Loslassen beendet, Esc bricht ab; X, Y oder Z gedrückt halten bewegt entlang dieser Achse.</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="63"/>
        <source>Moving crease %1 by %2 mm along the axis. Release to finish, Esc cancels.</source>
        <translation>Falz %1 wird um %2 mm entlang der Achse bewegt. Loslassen beendet, Esc bricht ab.</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool.cpp" line="509"/>
        <location filename="../app/gui/drag_tool.cpp" line="523"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ExampleDialog</name>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="23"/>
        <source>&amp;Hold the sheet it starts as</source>
        <translation>Den Bogen &amp;festhalten, aus dem es beginnt</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="25"/>
        <source>New from Example</source>
        <translation>Neu aus Beispiel</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="33"/>
        <source>&amp;Example:</source>
        <translation>&amp;Beispiel:</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="34"/>
        <source>&amp;Size:</source>
        <translation>&amp;Größe:</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="65"/>
        <source>Keep the development around the cylinder the design&apos;s unfolding rolls onto, as Tools ▸ Hold the Sheet does: a drag that the sheet cannot follow lags behind the mouse instead of stretching it.</source>
        <translation>Die Abwicklung um den Zylinder festhalten, auf den sich die Abwicklung des Entwurfs rollt, wie Werkzeuge ▸ Bogen festhalten es tut: Ein Ziehen, dem der Bogen nicht folgen kann, bleibt hinter der Maus zurück, statt ihn zu dehnen.</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="68"/>
        <source>Keep the development: the design stays foldable from the flat sheet it starts as, and a drag that the sheet cannot follow lags behind the mouse instead of stretching it. Of two pins at the ends of a straight line in the sheet only the first stays pinned, since the sheet would keep that line straight. Tools ▸ Hold the Sheet turns it off later.</source>
        <translation>Die Abwicklung festhalten: Der Entwurf bleibt aus dem ebenen Bogen faltbar, aus dem er beginnt, und ein Ziehen, dem der Bogen nicht folgen kann, bleibt hinter der Maus zurück, statt ihn zu dehnen. Von zwei Pins an den Enden einer geraden Linie im Bogen bleibt nur der erste gepinnt, da der Bogen diese Linie gerade hielte. Werkzeuge ▸ Bogen festhalten schaltet es später aus.</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="75"/>
        <source>This example comes holding its sheet.</source>
        <translation>Dieses Beispiel hält seinen Bogen bereits fest.</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="79"/>
        <source>A torus unfolds into no one sheet: it keeps local conditions only.</source>
        <translation>Ein Torus lässt sich in keinen einzelnen Bogen abwickeln: Er hält nur lokale Bedingungen ein.</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ExportJsonReaction</name>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="111"/>
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="96"/>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="113"/>
        <source>Export Interchange JSON</source>
        <translation>Austausch-JSON exportieren</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="97"/>
        <source>“%1” ends in .%2, but this command writes interchange JSON. Export to “%3” instead?</source>
        <translation>„%1“ endet auf .%2, dieser Befehl schreibt aber Austausch-JSON. Stattdessen nach „%3“ exportieren?</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="102"/>
        <source>Export as .json</source>
        <translation>Als .json exportieren</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="115"/>
        <source>Interchange JSON (*.json)</source>
        <translation>Austausch-JSON (*.json)</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="123"/>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="130"/>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="133"/>
        <source>Export failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="128"/>
        <source>Exported %1</source>
        <translation>%1 exportiert</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="134"/>
        <source>The design cannot be exported: %1</source>
        <translation>Der Entwurf kann nicht exportiert werden: %1</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ExportPatternReaction</name>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="84"/>
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="89"/>
        <source>Exported the cutting pattern</source>
        <translation>Schnittmuster exportiert</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ExportShapeReaction</name>
    <message>
        <location filename="../app/gui/reactions/shape_reactions.cpp" line="23"/>
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/shape_reactions.cpp" line="28"/>
        <source>Exported the 3D shape (%1)</source>
        <translation>3D-Form exportiert (%1)</translation>
    </message>
</context>
<context>
    <name>devsurf::app::FitEdgeToCurveReaction</name>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="185"/>
        <source>Lay a crease or boundary onto a reference curve: import curves first (File ▸ Import Curves…).</source>
        <translation>Eine Falz oder einen Rand an eine Referenzkurve anlegen: zuerst Kurven importieren (Datei ▸ Kurven importieren…).</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="187"/>
        <source>Lay a crease or boundary onto a reference curve: select one spline edge.</source>
        <translation>Eine Falz oder einen Rand an eine Referenzkurve anlegen: wählen Sie eine Splinekante.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="188"/>
        <source>Lay the selected crease or boundary onto the reference curve nearest it; Solve then makes the surface developable again.</source>
        <translation>Die gewählte Falz oder den gewählten Rand an die nächstgelegene Referenzkurve anlegen; Lösen macht die Fläche danach wieder abwickelbar.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="211"/>
        <source>Edge %1 was not fitted: both its ends are nearest the same point of %2.</source>
        <translation>Kante %1 wurde nicht angelegt: beide Enden liegen demselben Punkt von %2 am nächsten.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="214"/>
        <source>Edge %1 was not fitted: %2 has too few points.</source>
        <translation>Kante %1 wurde nicht angelegt: %2 hat zu wenige Punkte.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="218"/>
        <source>Fit Edge to Curve</source>
        <translation>Kante an Kurve anlegen</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="220"/>
        <source>Cannot fit the edge to the curve</source>
        <translation>Die Kante kann nicht an die Kurve angelegt werden</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="225"/>
        <source>Edge %1 lies on %2 within %3 mm; Solve (Ctrl+Return) makes the surface developable again.</source>
        <translation>Kante %1 liegt bis auf %3 mm auf %2; Lösen (Ctrl+Return) macht die Fläche wieder abwickelbar.</translation>
    </message>
</context>
<context>
    <name>devsurf::app::HoldSheetReaction</name>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="79"/>
        <source>Hold the sheet of a surface: select something on one surface first.</source>
        <translation>Den Bogen einer Fläche festhalten: zuerst etwas auf einer Fläche auswählen.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="80"/>
        <source>The surface is folded from its sheet: solves and drags keep it isometric to its development, and a dragged vertex stays behind where the sheet cannot follow. Uncheck to let the sheet stretch again.</source>
        <translation>Die Fläche ist aus ihrem Bogen gefaltet: Lösen und Ziehen halten sie isometrisch zu ihrer Abwicklung, und ein gezogener Eckpunkt bleibt zurück, wo der Bogen nicht folgen kann. Abwählen, damit sich der Bogen wieder dehnen darf.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="83"/>
        <source>Fold the surface from its sheet: its development as it unfolds now is kept by every solve and drag; a dragged vertex stays behind where the sheet cannot follow, instead of the sheet stretching.</source>
        <translation>Die Fläche aus ihrem Bogen falten: ihre Abwicklung, wie sie sich jetzt abwickelt, wird von jedem Lösen und Ziehen beibehalten; ein gezogener Eckpunkt bleibt zurück, wo der Bogen nicht folgen kann, statt dass sich der Bogen dehnt.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="99"/>
        <source>Hold the Sheet</source>
        <translation>Bogen festhalten</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="99"/>
        <source>Let the Sheet Stretch</source>
        <translation>Bogen dehnen lassen</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="102"/>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="113"/>
        <source>Cannot hold the sheet</source>
        <translation>Der Bogen kann nicht festgehalten werden</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="113"/>
        <source>Cannot let the sheet stretch</source>
        <translation>Der Bogen kann nicht freigegeben werden</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ImportCurvesReaction</name>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="39"/>
        <source>%1 is not a file DevSurf reads curves from; choose a DXF, SVG, STEP or IGES file.</source>
        <translation>Aus %1 kann DevSurf keine Kurven lesen; wählen Sie eine DXF-, SVG-, STEP- oder IGES-Datei.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="42"/>
        <source>This build of DevSurf reads curves from DXF and SVG files only; save the curves as DXF.</source>
        <translation>Diese DevSurf-Version liest Kurven nur aus DXF- und SVG-Dateien; speichern Sie die Kurven als DXF.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="45"/>
        <source>%1 cannot be read; check that it exists and that you may read it.</source>
        <translation>%1 kann nicht gelesen werden; prüfen Sie, ob die Datei existiert und Sie sie lesen dürfen.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="49"/>
        <source>%1 is too large to import curves from.</source>
        <translation>%1 ist zu groß, um Kurven daraus zu importieren.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="51"/>
        <source>%1 is damaged or not a valid file of its type; nothing was imported.</source>
        <translation>%1 ist beschädigt oder keine gültige Datei ihres Typs; es wurde nichts importiert.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="55"/>
        <source>%1 holds no lines, polylines, splines, arcs or circles to import.</source>
        <translation>%1 enthält keine Linien, Polylinien, Splines, Bögen oder Kreise zum Importieren.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="61"/>
        <source>The curves of %1 could not be imported.</source>
        <translation>Die Kurven von %1 konnten nicht importiert werden.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="82"/>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="99"/>
        <source>Import Curves</source>
        <translation>Kurven importieren</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="83"/>
        <source>Curve files (*.dxf *.svg *.step *.stp *.iges *.igs);;DXF (*.dxf);;SVG (*.svg);;STEP (*.step *.stp);;IGES (*.iges *.igs)</source>
        <translation>Kurvendateien (*.dxf *.svg *.step *.stp *.iges *.igs);;DXF (*.dxf);;SVG (*.svg);;STEP (*.step *.stp);;IGES (*.iges *.igs)</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="98"/>
        <source>Reading curves from %1…</source>
        <translation>Kurven aus %1 werden gelesen…</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="123"/>
        <source>Import of curves from %1 cancelled</source>
        <translation>Import der Kurven aus %1 abgebrochen</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="125"/>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="131"/>
        <source>Cannot import curves</source>
        <translation>Kurven können nicht importiert werden</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="133"/>
        <source>Imported the curves of %1</source>
        <translation>Die Kurven von %1 wurden importiert</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ImportReferenceShapeReaction</name>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="81"/>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="99"/>
        <source>Import Reference Shape</source>
        <translation>Referenzform importieren</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="83"/>
        <source>Meshes and point clouds (*.obj *.ply *.stl *.off *.xyz *.pts);;Meshes (*.obj *.ply *.stl *.off);;Point clouds (*.xyz *.pts)</source>
        <translation>Netze und Punktwolken (*.obj *.ply *.stl *.off *.xyz *.pts);;Netze (*.obj *.ply *.stl *.off);;Punktwolken (*.xyz *.pts)</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="98"/>
        <source>Reading reference shape %1…</source>
        <translation>Referenzform %1 wird gelesen…</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="122"/>
        <source>Import of reference shape %1 cancelled</source>
        <translation>Import der Referenzform %1 abgebrochen</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="124"/>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="133"/>
        <source>Cannot import the reference shape</source>
        <translation>Die Referenzform kann nicht importiert werden</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="135"/>
        <source>Imported reference shape %1: %2, %3</source>
        <translation>Referenzform %1 importiert: %2, %3</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="136"/>
        <source>%n point(s)</source>
        <translation>
            <numerusform>%n Punkt</numerusform>
            <numerusform>%n Punkte</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="137"/>
        <source>%n triangle(s)</source>
        <translation>
            <numerusform>%n Dreieck</numerusform>
            <numerusform>%n Dreiecke</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::JoinReaction</name>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="41"/>
        <source>Join Surfaces</source>
        <translation>Flächen verbinden</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="81"/>
        <source>Join surfaces into one composite: wait until the solver has finished, or cancel it (Esc).</source>
        <translation>Flächen zu einer zusammengesetzten Fläche verbinden: warten, bis der Löser fertig ist, oder ihn abbrechen (Esc).</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="83"/>
        <source>Join the selected surfaces (all when fewer than two are selected) into one composite: boundary curves or rulings that face each other become shared edges, held to the reference shapes where there are any; one undo step.</source>
        <translation>Die ausgewählten Flächen (alle, wenn weniger als zwei ausgewählt sind) zu einer zusammengesetzten Fläche verbinden: einander gegenüberliegende Randkurven oder Erzeugende werden gemeinsame Kanten, an den Referenzformen gehalten, wo es welche gibt; ein Rückgängig-Schritt.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="106"/>
        <source>Preparing the join: thinning the reference shapes…</source>
        <translation>Verbinden wird vorbereitet: Referenzformen ausdünnen…</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="140"/>
        <source>Join cancelled; the design is unchanged.</source>
        <translation>Verbinden abgebrochen; der Entwurf ist unverändert.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="144"/>
        <source>Join discarded: the design changed meanwhile; it is unchanged.</source>
        <translation>Verbinden verworfen: der Entwurf hat sich inzwischen geändert; er ist unverändert.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="79"/>
        <source>Join surfaces into one composite where their boundary edges face each other: the design needs at least two surfaces.</source>
        <translation>Flächen zu einer zusammengesetzten Fläche verbinden, wo ihre Randkanten einander gegenüberliegen: der Entwurf braucht mindestens zwei Flächen.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="133"/>
        <source>The reference shapes could not be thinned for the join (%1); nothing was joined.</source>
        <translation>Die Referenzformen konnten für das Verbinden nicht ausgedünnt werden (%1); nichts wurde verbunden.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="135"/>
        <source>Cannot join the surfaces</source>
        <translation>Die Flächen können nicht verbunden werden</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/join_reaction.cpp" line="174"/>
        <source>No two of the %n surface(s) have boundary edges facing each other (within %1 % of their length); nothing was joined.</source>
        <translation>
            <numerusform>Die %n Fläche hat keine Randkanten, die einer anderen gegenüberliegen (innerhalb von %1 % ihrer Länge); nichts wurde verbunden.</numerusform>
            <numerusform>Keine zwei der %n Flächen haben einander gegenüberliegende Randkanten (innerhalb von %1 % ihrer Länge); nichts wurde verbunden.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="192"/>
        <source>%1 failed: %2 The design is unchanged.</source>
        <translation>%1 fehlgeschlagen: %2 Der Entwurf ist unverändert.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/join_reaction.cpp" line="201"/>
        <source>Joined %n surface(s) into one: </source>
        <translation>
            <numerusform>%n Fläche zu einer verbunden: </numerusform>
            <numerusform>%n Flächen zu einer verbunden: </numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/join_reaction.cpp" line="202"/>
        <source>%1 of %n pair(s) of facing edges welded</source>
        <translation>
            <numerusform>%1 von %n Paar gegenüberliegender Kanten verschweißt</numerusform>
            <numerusform>%1 von %n Paaren gegenüberliegender Kanten verschweißt</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/join_reaction.cpp" line="203"/>
        <source>, %n part(s) not connected</source>
        <translation>
            <numerusform>, %n Teil nicht verbunden</numerusform>
            <numerusform>, %n Teile nicht verbunden</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="206"/>
        <source>largest constraint residual %1, within the tolerance.</source>
        <translation>größtes Bedingungsresiduum %1, innerhalb der Toleranz.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="207"/>
        <source>largest constraint residual %1, not within the tolerance (Tools ▸ Solve may help).</source>
        <translation>größtes Bedingungsresiduum %1, nicht innerhalb der Toleranz (Werkzeuge ▸ Lösen kann helfen).</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="211"/>
        <source>Not welded: %1</source>
        <translation>Nicht verschweißt: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/join_reaction.cpp" line="215"/>
        <source>%n surface(s) facing no other were left as they are.</source>
        <translation>
            <numerusform>%n Fläche, die keiner anderen gegenüberliegt, blieb unverändert.</numerusform>
            <numerusform>%n Flächen, die keiner anderen gegenüberliegen, blieben unverändert.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="220"/>
        <source>The surfaces were held to the reference shape meanwhile.</source>
        <translation>Die Flächen wurden dabei an der Referenzform gehalten.</translation>
    </message>
</context>
<context>
    <name>devsurf::app::MainWindow</name>
    <message>
        <location filename="../app/gui/main_window.cpp" line="127"/>
        <source>Patches</source>
        <translation>Flächenstücke</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="133"/>
        <source>Properties</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="139"/>
        <source>Pins</source>
        <translation>Festgehaltene Ecken</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="149"/>
        <source>Solver</source>
        <translation>Löser</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="169"/>
        <source>Main</source>
        <translation>Haupt</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="176"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="178"/>
        <source>&amp;New from Example…</source>
        <translation>&amp;Neu aus Beispiel…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="180"/>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="182"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="186"/>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="189"/>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="193"/>
        <source>Import &amp;Curves…</source>
        <translation>&amp;Kurven importieren…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="198"/>
        <source>Import Reference S&amp;hape…</source>
        <translation>Referenz&amp;form importieren…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="199"/>
        <source>Add a mesh (OBJ, PLY, STL, OFF) or a point cloud (XYZ, PTS) the design is to follow, as a reference shape</source>
        <translation>Ein Netz (OBJ, PLY, STL, OFF) oder eine Punktwolke (XYZ, PTS), der der Entwurf folgen soll, als Referenzform hinzufügen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="203"/>
        <source>&amp;Export Interchange JSON…</source>
        <translation>Austausch-JSON &amp;exportieren…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="203"/>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="206"/>
        <source>Export &amp;3D Shape…</source>
        <translation>&amp;3D-Form exportieren…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="210"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="214"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="217"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="220"/>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="227"/>
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="230"/>
        <source>Remove Reference &amp;Curves</source>
        <translation>Referenz&amp;kurven entfernen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="233"/>
        <source>Remove Reference S&amp;hapes</source>
        <translation>Referenz&amp;formen entfernen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="235"/>
        <source>Select &amp;None</source>
        <translation>Auswahl &amp;aufheben</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="236"/>
        <location filename="../app/gui/main_window_solver.cpp" line="128"/>
        <source>Esc</source>
        <translation>Esc</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="240"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="242"/>
        <source>&amp;3D View</source>
        <translation>&amp;3D-Ansicht</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="242"/>
        <source>Ctrl+1</source>
        <translation>Ctrl+1</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="244"/>
        <source>&amp;Development View</source>
        <translation>&amp;Abwicklung</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="244"/>
        <source>Ctrl+2</source>
        <translation>Ctrl+2</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="245"/>
        <source>3D &amp;and Development</source>
        <translation>3D &amp;und Abwicklung</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="246"/>
        <source>Ctrl+3</source>
        <translation>Ctrl+3</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="250"/>
        <source>&amp;Control Polygons</source>
        <translation>&amp;Kontrollpolygone</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="250"/>
        <source>Ctrl+Shift+P</source>
        <translation>Ctrl+Shift+P</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="251"/>
        <source>&amp;Vertices</source>
        <translation>&amp;Ecken</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="252"/>
        <source>Ctrl+Shift+V</source>
        <translation>Ctrl+Shift+V</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="255"/>
        <source>S&amp;heet Outline</source>
        <translation>&amp;Bogenumriss</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="258"/>
        <source>Draw the sheet a held development is confined to behind it in the development view (Tools ▸ Sheet Shape…).</source>
        <translation>Den Bogen, auf den eine gehaltene Abwicklung beschränkt ist, in der Abwicklungsansicht dahinter zeichnen (Werkzeuge ▸ Bogenform…).</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="268"/>
        <source>&amp;Reference Shapes</source>
        <translation>&amp;Referenzformen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="271"/>
        <source>Draw the imported meshes and point clouds in the 3D view (File ▸ Import Reference Shape…).</source>
        <translation>Die importierten Netze und Punktwolken in der 3D-Ansicht zeichnen (Datei ▸ Referenzform importieren…).</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="286"/>
        <source>Colour the points of the reference shapes by their distance to the design, in mm, with a legend (green: within the coverage tolerance of Tools ▸ Distance to Reference…).</source>
        <translation>Färbt die Punkte der Referenzformen nach ihrem Abstand zum Entwurf, in mm, mit Legende (grün: innerhalb der Abdeckungstoleranz von Werkzeuge ▸ Abstand zur Referenzform…).</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="297"/>
        <source>&amp;Fit All</source>
        <translation>&amp;Alles zeigen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="297"/>
        <source>F</source>
        <translation>F</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="303"/>
        <source>Reset &amp;Layout</source>
        <translation>&amp;Layout zurücksetzen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="308"/>
        <source>&amp;Tools</source>
        <translation>&amp;Werkzeuge</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="311"/>
        <source>&amp;Relabel Edge (R ↔ S)</source>
        <translation>Kanten&amp;kennzeichnung ändern (R ↔ S)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="311"/>
        <source>Ctrl+L</source>
        <translation>Ctrl+L</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="313"/>
        <source>Add &amp;Crease…</source>
        <translation>&amp;Falz einfügen…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="316"/>
        <source>Add R&amp;uling…</source>
        <translation>&amp;Erzeugende einfügen…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="320"/>
        <source>Remove Rulin&amp;g</source>
        <translation>Erzeu&amp;gende entfernen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="320"/>
        <source>Ctrl+Alt+R</source>
        <translation>Ctrl+Alt+R</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="332"/>
        <source>&amp;Pin Vertices</source>
        <translation>Ecken &amp;festhalten</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="333"/>
        <source>Ctrl+K</source>
        <translation>Ctrl+K</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="335"/>
        <source>U&amp;npin Vertices</source>
        <translation>Ecken &amp;freigeben</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="336"/>
        <source>Ctrl+Shift+K</source>
        <translation>Ctrl+Shift+K</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="339"/>
        <source>Hold the &amp;Sheet</source>
        <translation>&amp;Bogen festhalten</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="340"/>
        <source>Ctrl+Shift+H</source>
        <translation>Ctrl+Shift+H</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="343"/>
        <source>Sheet S&amp;hape…</source>
        <translation>Bogen&amp;form…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="350"/>
        <source>A&amp;pproximate Reference Shape…</source>
        <translation>Referenzform an&amp;nähern…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="358"/>
        <source>&amp;Join Surfaces</source>
        <translation>Flächen &amp;verbinden</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="359"/>
        <source>Ctrl+J</source>
        <translation>Ctrl+J</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="363"/>
        <source>Mar&amp;k Region of Reference Shape</source>
        <translation>Bereich der Referenzform mar&amp;kieren</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="363"/>
        <source>L</source>
        <translation>L</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="365"/>
        <source>Add Strip O&amp;ver Marked Region</source>
        <translation>Streifen über markiertem Bereich hin&amp;zufügen</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/main_window.cpp" line="501"/>
        <source>%n surface(s)</source>
        <translation>
            <numerusform>%n Fläche</numerusform>
            <numerusform>%n Flächen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/main_window.cpp" line="502"/>
        <source>%n patch(es)</source>
        <translation>
            <numerusform>%n Flächenstück</numerusform>
            <numerusform>%n Flächenstücke</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/main_window.cpp" line="503"/>
        <source>%n control point(s)</source>
        <translation>
            <numerusform>%n Kontrollpunkt</numerusform>
            <numerusform>%n Kontrollpunkte</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/main_window.cpp" line="504"/>
        <source>%n selected</source>
        <translation>
            <numerusform>%n ausgewählt</numerusform>
            <numerusform>%n ausgewählt</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="314"/>
        <source>Ctrl+D</source>
        <translation>Ctrl+D</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="195"/>
        <source>Add the curves of a DXF, SVG, STEP or IGES file as reference curves</source>
        <translation>Die Kurven einer DXF-, SVG-, STEP- oder IGES-Datei als Referenzkurven hinzufügen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="282"/>
        <source>Colour Reference by Dis&amp;tance</source>
        <translation>Referenzform nach Abs&amp;tand färben</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="317"/>
        <source>Ctrl+R</source>
        <translation>Ctrl+R</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="322"/>
        <source>Re&amp;fine Curves</source>
        <translation>Kurven &amp;verfeinern</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="323"/>
        <source>Ctrl+Shift+R</source>
        <translation>Ctrl+Shift+R</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="329"/>
        <source>&amp;Move or Rotate Vertices…</source>
        <translation>Ecken &amp;verschieben oder drehen…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="329"/>
        <source>Ctrl+M</source>
        <translation>Ctrl+M</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="347"/>
        <source>Dis&amp;tance to Reference…</source>
        <translation>Abs&amp;tand zur Referenzform…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="402"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="403"/>
        <source>&amp;User Manual</source>
        <translation>&amp;Benutzerhandbuch</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="410"/>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>&amp;Tastenkürzel</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="416"/>
        <source>&amp;About DevSurf</source>
        <translation>&amp;Über DevSurf</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="418"/>
        <source>About DevSurf</source>
        <translation>Über DevSurf</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="419"/>
        <source>&lt;b&gt;DevSurf %1&lt;/b&gt;&lt;p&gt;Design of developable surfaces and curved-crease origami with spline developables (Tang, Bo, Wallner, Pottmann 2015).&lt;/p&gt;</source>
        <translation>&lt;b&gt;DevSurf %1&lt;/b&gt;&lt;p&gt;Entwurf abwickelbarer Flächen und Origami mit gekrümmten Falzen mit Spline-Torsen (Tang, Bo, Wallner, Pottmann 2015).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="464"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="486"/>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="487"/>
        <source>%1[*] — DevSurf</source>
        <translation>%1[*] — DevSurf</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="30"/>
        <source>&amp;Solve</source>
        <translation>&amp;Lösen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="31"/>
        <source>Ctrl+Return</source>
        <translation>Ctrl+Return</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/main_window_solver.cpp" line="34"/>
        <source>Make every surface developable again: %n iteration(s) of the solver, one undo step. Pinned vertices stay where they are.</source>
        <translation>
            <numerusform>Macht jede Fläche wieder abwickelbar: %n Iteration des Lösers, ein Rückgängig-Schritt. Festgehaltene Ecken bleiben, wo sie sind.</numerusform>
            <numerusform>Macht jede Fläche wieder abwickelbar: %n Iterationen des Lösers, ein Rückgängig-Schritt. Festgehaltene Ecken bleiben, wo sie sind.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="42"/>
        <source>Solver &amp;Iterations…</source>
        <translation>Löser-&amp;Iterationen…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="44"/>
        <source>The most solver iterations Tools ▸ Solve runs; it stops earlier once the surface has converged.</source>
        <translation>Höchstzahl der Iterationen von Werkzeuge ▸ Lösen; es endet früher, sobald die Fläche konvergiert ist.</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="49"/>
        <source>Solver Iterations</source>
        <translation>Löser-Iterationen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="49"/>
        <source>Most iterations of Tools ▸ Solve:</source>
        <translation>Höchstzahl der Iterationen von Werkzeuge ▸ Lösen:</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="82"/>
        <source>R&amp;otate Vertices</source>
        <translation>Ecken dr&amp;ehen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="83"/>
        <source>R</source>
        <translation>R</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="86"/>
        <source>Rotate tool (R): select two or more vertices, press on a vertex in the 3D view and move the mouse sideways; they turn about an axis through their centroid (vertical, or as chosen in the toolbar) and the surface follows. Esc cancels.</source>
        <translation>Drehwerkzeug (R): Wählen Sie zwei oder mehr Ecken aus, drücken Sie in der 3D-Ansicht auf eine Ecke und bewegen Sie die Maus seitwärts; sie drehen sich um eine Achse durch ihren Schwerpunkt (senkrecht oder wie in der Werkzeugleiste gewählt), und die Fläche folgt. Esc bricht ab.</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="95"/>
        <source>Measure tool: click two points of the surface in the 3D view; their distance in space and along the sheet (as the cut pattern has it) is drawn and shown in the status bar. Select an edge for its length, two edges that meet for their angle.</source>
        <translation>Messwerkzeug: klicken Sie in der 3D-Ansicht auf zwei Punkte der Fläche; ihr Abstand im Raum und entlang des Bogens (wie ihn das Schnittmuster hat) wird eingezeichnet und in der Statusleiste angezeigt. Wählen Sie eine Kante für ihre Länge, zwei sich treffende Kanten für ihren Winkel.</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="119"/>
        <source>Finish the drag first; it solves as it goes.</source>
        <translation>Beenden Sie zuerst das Ziehen; es löst bereits während der Bewegung.</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="58"/>
        <source>G</source>
        <translation>G</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="58"/>
        <source>&amp;Drag Vertices and Creases</source>
        <translation>Ecken und Falze &amp;ziehen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="61"/>
        <source>Drag tool: press on a vertex in the 3D view and move it, the surface follows and stays developable; press on a crease to slide it within its patches. The axis chosen in the toolbar, or holding X, Y or Z, moves along that axis; Esc cancels the drag (G).</source>
        <translation>Ziehwerkzeug: Drücken Sie in der 3D-Ansicht auf eine Ecke und bewegen Sie sie, die Fläche folgt und bleibt abwickelbar; drücken Sie auf einen Falz, um ihn innerhalb seiner Flächenstücke zu verschieben. Die in der Werkzeugleiste gewählte Achse oder gedrückt gehaltenes X, Y oder Z bewegt entlang dieser Achse; Esc bricht das Ziehen ab (G).</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="70"/>
        <source>S&amp;nap to Reference Curves</source>
        <translation>An Referenzkurven &amp;fangen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="72"/>
        <source>While dragging a vertex (no axis chosen), put it on the nearest reference curve drawn within 10 pixels of the mouse.</source>
        <translation>Beim Ziehen eines Eckpunkts (ohne gewählte Achse) wird er auf die nächste Referenzkurve gesetzt, die höchstens 10 Pixel von der Maus entfernt gezeichnet ist.</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="78"/>
        <source>&amp;Fit Edge to Reference Curve</source>
        <translation>Kante an Referenzkurve an&amp;legen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="93"/>
        <source>Measur&amp;e</source>
        <translation>&amp;Messen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="101"/>
        <source>Cop&amp;y Measurement</source>
        <translation>Messung kop&amp;ieren</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="101"/>
        <source>Ctrl+C</source>
        <translation>Ctrl+C</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="102"/>
        <source>Copy the last measurement to the clipboard (Ctrl+C).</source>
        <translation>Die letzte Messung in die Zwischenablage kopieren (Ctrl+C).</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="127"/>
        <source>&amp;Cancel Solve</source>
        <translation>Lösen &amp;abbrechen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="130"/>
        <source>Stop the running solve; the design stays as it is (Esc).</source>
        <translation>Das laufende Lösen beenden; der Entwurf bleibt, wie er ist (Esc).</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="154"/>
        <source>Solving: iteration %1 of %2, residual %3</source>
        <translation>Lösen: Iteration %1 von %2, Residuum %3</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="167"/>
        <source>&amp;Lengths While Dragging</source>
        <translation>&amp;Längen beim Ziehen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="179"/>
        <source>&amp;Automatic</source>
        <translation>&amp;Automatisch</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="180"/>
        <source>Vertex drags and rotations keep lengths. Where the sheet cannot follow that way (the drag does not converge, folds over, collapses a strip or its development overlaps itself), the drag is replayed on release letting the sheet stretch, and the better of the two is kept; the Solver panel says so.</source>
        <translation>Das Ziehen und Drehen von Ecken behält die Längen bei. Wo das Blatt so nicht folgen kann (das Ziehen konvergiert nicht, faltet sich zurück, lässt einen Streifen zusammenfallen oder seine Abwicklung überlappt sich selbst), wird es beim Loslassen mit Dehnen des Blatts wiederholt, und das bessere der beiden Ergebnisse bleibt; das Löser-Fenster sagt es.</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="184"/>
        <source>&amp;Keep Lengths</source>
        <translation>Längen &amp;beibehalten</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="185"/>
        <source>While dragging or rotating vertices, the sheet bends instead of stretching: far parts stay in place and curved creases keep their shape and fold. A motion the sheet cannot make without stretching then may not converge. Dragged creases always resize their patches.</source>
        <translation>Beim Ziehen oder Drehen von Ecken biegt sich das Blatt, statt sich zu dehnen: entfernte Teile bleiben an ihrem Platz, und gekrümmte Falze behalten ihre Form und falten sich. Eine Bewegung, die das Blatt nicht ohne Dehnen ausführen kann, konvergiert dann unter Umständen nicht. Gezogene Falze ändern die Größe ihrer Flächenstücke immer.</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="189"/>
        <source>Let &amp;Stretch</source>
        <translation>&amp;Dehnen zulassen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="190"/>
        <source>While dragging or rotating vertices, the sheet may stretch: it stays developable and its development changes, curved creases may be pulled straight and large drags may crumple it.</source>
        <translation>Beim Ziehen oder Drehen von Ecken darf sich das Blatt dehnen: es bleibt abwickelbar und seine Abwicklung ändert sich, gekrümmte Falze können gerade gezogen werden, und große Bewegungen können es zerknittern.</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="212"/>
        <source>Motion &amp;Axis</source>
        <translation>Bewegungs&amp;achse</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="224"/>
        <source>&amp;Free</source>
        <translation>&amp;Frei</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="225"/>
        <source>Free motion: the Drag tool moves vertices in the view plane; the Rotate tool turns them about the vertical axis (Z), or about the view axis if Tools ▸ Motion Axis ▸ Rotate About the View Axis is on.</source>
        <translation>Freie Bewegung: Das Ziehwerkzeug bewegt Ecken in der Bildebene; das Drehwerkzeug dreht sie um die senkrechte Achse (Z) oder um die Blickachse, wenn Werkzeuge ▸ Bewegungsachse ▸ Um die Blickachse drehen eingeschaltet ist.</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="228"/>
        <source>&amp;X Axis</source>
        <translation>&amp;X-Achse</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="229"/>
        <source>X axis: the Drag tool moves vertices along X only; the Rotate tool turns them about an X-parallel axis through their centroid. Holding Y or Z overrides.</source>
        <translation>X-Achse: Das Ziehwerkzeug bewegt Ecken nur entlang X; das Drehwerkzeug dreht sie um eine zu X parallele Achse durch ihren Schwerpunkt. Gedrückt gehaltenes Y oder Z hat Vorrang.</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="231"/>
        <source>&amp;Y Axis</source>
        <translation>&amp;Y-Achse</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="232"/>
        <source>Y axis: the Drag tool moves vertices along Y only; the Rotate tool turns them about a Y-parallel axis through their centroid. Holding X or Z overrides.</source>
        <translation>Y-Achse: Das Ziehwerkzeug bewegt Ecken nur entlang Y; das Drehwerkzeug dreht sie um eine zu Y parallele Achse durch ihren Schwerpunkt. Gedrückt gehaltenes X oder Z hat Vorrang.</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="234"/>
        <source>&amp;Z Axis</source>
        <translation>&amp;Z-Achse</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="235"/>
        <source>Z axis: the Drag tool moves vertices along Z only; the Rotate tool turns them about a Z-parallel axis through their centroid. Holding X or Y overrides.</source>
        <translation>Z-Achse: Das Ziehwerkzeug bewegt Ecken nur entlang Z; das Drehwerkzeug dreht sie um eine zu Z parallele Achse durch ihren Schwerpunkt. Gedrückt gehaltenes X oder Y hat Vorrang.</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="259"/>
        <source>Rotate About the &amp;View Axis</source>
        <translation>Um die &amp;Blickachse drehen</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="262"/>
        <source>With the axis choice Free, the Rotate tool turns the vertices about the viewing direction through their centroid instead of the vertical axis.</source>
        <translation>Bei der Achswahl „Frei“ dreht das Drehwerkzeug die Ecken um die Blickrichtung durch ihren Schwerpunkt statt um die senkrechte Achse.</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="276"/>
        <source>Colour &amp;By</source>
        <translation>&amp;Färben nach</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="284"/>
        <source>&amp;Patch</source>
        <translation>&amp;Flächenstück</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="284"/>
        <source>&amp;Developability</source>
        <translation>&amp;Abwickelbarkeit</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="284"/>
        <source>&amp;Flatness</source>
        <translation>&amp;Ebenheit</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="285"/>
        <source>&amp;Angle Defect</source>
        <translation>&amp;Winkeldefekt</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="287"/>
        <source>Every patch in its own colour.</source>
        <translation>Jedes Flächenstück in seiner eigenen Farbe.</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="288"/>
        <source>How far every sampled strip quad is from developable: the normalised |det(a−b, a′, b′)|, on a logarithmic scale.</source>
        <translation>Wie weit jedes abgetastete Streifenviereck von abwickelbar entfernt ist: das normierte |det(a−b, a′, b′)|, logarithmisch skaliert.</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="290"/>
        <source>Flatness δ of every sampled quad: the distance of its diagonals over the mean of its two shortest edges, on a logarithmic scale.</source>
        <translation>Ebenheit δ jedes abgetasteten Vierecks: der Abstand seiner Diagonalen durch das Mittel seiner zwei kürzesten Kanten, logarithmisch skaliert.</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="292"/>
        <source>Angle defect |K| = |2π − Σ angles| at the interior vertices of the sampled mesh, in radians, on a logarithmic scale.</source>
        <translation>Winkeldefekt |K| = |2π − Σ Winkel| an den inneren Ecken des abgetasteten Netzes, im Bogenmaß, logarithmisch skaliert.</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ManualWindow</name>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="56"/>
        <source>DevSurf User Manual</source>
        <translation>DevSurf-Benutzerhandbuch</translation>
    </message>
</context>
<context>
    <name>devsurf::app::MarkRegionTool</name>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="92"/>
        <source>Mark a region of the reference shape: drag a lasso around it in the 3D view (Shift adds to the mark, a click clears it, Esc leaves the tool), then Enter adds a flat strip over it (L).</source>
        <translation>Einen Bereich der Referenzform markieren: in der 3D-Ansicht ein Lasso darum ziehen (Umschalt fügt zur Markierung hinzu, ein Klick löscht sie, Esc verlässt das Werkzeug), dann fügt Eingabe einen ebenen Streifen darüber hinzu (L).</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="95"/>
        <source>Mark a region of the reference shape with a lasso: import one first (File ▸ Import Reference Shape…).</source>
        <translation>Einen Bereich der Referenzform mit einem Lasso markieren: zuerst eine importieren (Datei ▸ Referenzform importieren…).</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="102"/>
        <source>Add a flat strip fitted to the marked points (their PCA plane), one undo step; Tools ▸ Approximate Reference Shape… with the design&apos;s surfaces then pulls it onto the shape.</source>
        <translation>Einen ebenen Streifen, an die markierten Punkte angepasst (ihre PCA-Ebene), hinzufügen, ein Rückgängig-Schritt; Werkzeuge ▸ Referenzform annähern… mit den Flächen des Entwurfs zieht ihn dann auf die Form.</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="105"/>
        <source>Add a flat strip over a marked region of the reference shape: mark one first (Tools ▸ Mark Region of Reference Shape).</source>
        <translation>Einen ebenen Streifen über einem markierten Bereich der Referenzform hinzufügen: zuerst einen markieren (Werkzeuge ▸ Bereich der Referenzform markieren).</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="117"/>
        <source>Mark region: drag a lasso around part of the reference shape in the 3D view; Shift adds to the mark, Enter adds a strip over it, Esc leaves the tool.</source>
        <translation>Bereich markieren: in der 3D-Ansicht ein Lasso um einen Teil der Referenzform ziehen; Umschalt fügt zur Markierung hinzu, Eingabe fügt einen Streifen darüber hinzu, Esc verlässt das Werkzeug.</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="166"/>
        <source>Lasso dropped; the mark is as it was.</source>
        <translation>Lasso verworfen; die Markierung ist wie zuvor.</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="234"/>
        <source>Mark cleared.</source>
        <translation>Markierung gelöscht.</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="239"/>
        <source>The reference shapes are hidden: show them (View ▸ Reference Shapes) to mark a region.</source>
        <translation>Die Referenzformen sind ausgeblendet: zum Markieren einblenden (Ansicht ▸ Referenzformen).</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="260"/>
        <source>No point of the reference shape facing the camera lies inside the lasso; nothing is marked.</source>
        <translation>Kein der Kamera zugewandter Punkt der Referenzform liegt im Lasso; nichts ist markiert.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/mark_region_tool.cpp" line="274"/>
        <source>%Ln point(s) of %1 marked.</source>
        <translation>
            <numerusform>%Ln Punkt von %1 markiert.</numerusform>
            <numerusform>%Ln Punkte von %1 markiert.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/mark_region_tool.cpp" line="276"/>
        <source>%Ln point(s) of the reference shapes marked.</source>
        <translation>
            <numerusform>%Ln Punkt der Referenzformen markiert.</numerusform>
            <numerusform>%Ln Punkte der Referenzformen markiert.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="278"/>
        <source>%1 Enter adds a strip over them; Shift and a lasso add to the mark.</source>
        <translation>%1 Eingabe fügt einen Streifen darüber hinzu; Umschalt und ein Lasso fügen zur Markierung hinzu.</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="297"/>
        <source>No region is marked: draw a lasso around part of the reference shape first (Tools ▸ Mark Region of Reference Shape).</source>
        <translation>Kein Bereich ist markiert: zuerst ein Lasso um einen Teil der Referenzform ziehen (Werkzeuge ▸ Bereich der Referenzform markieren).</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="302"/>
        <source>Too few points are marked for a strip: mark at least three points that do not lie on a line.</source>
        <translation>Für einen Streifen sind zu wenige Punkte markiert: mindestens drei Punkte markieren, die nicht auf einer Geraden liegen.</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="310"/>
        <source>The marked points lie on a line, so no plane fits them: mark a region that is wide in two directions.</source>
        <translation>Die markierten Punkte liegen auf einer Geraden, also passt keine Ebene zu ihnen: einen Bereich markieren, der in zwei Richtungen breit ist.</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="319"/>
        <source>Add Strip Over Marked Region</source>
        <translation>Streifen über markiertem Bereich hinzufügen</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="320"/>
        <source>Cannot add the strip</source>
        <translation>Der Streifen kann nicht hinzugefügt werden</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/mark_region_tool.cpp" line="325"/>
        <source>Added strip %1 over %Ln marked point(s); Tools ▸ Approximate Reference Shape… with the design&apos;s surfaces pulls it onto the shape.</source>
        <translation>
            <numerusform>Streifen %1 über %Ln markiertem Punkt hinzugefügt; Werkzeuge ▸ Referenzform annähern… mit den Flächen des Entwurfs zieht ihn auf die Form.</numerusform>
            <numerusform>Streifen %1 über %Ln markierten Punkten hinzugefügt; Werkzeuge ▸ Referenzform annähern… mit den Flächen des Entwurfs zieht ihn auf die Form.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::MeasureTool</name>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="39"/>
        <source>Measure: click two points of the surface in the 3D view.</source>
        <translation>Messen: klicken Sie in der 3D-Ansicht auf zwei Punkte der Fläche.</translation>
    </message>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="48"/>
        <source>Copied: %1</source>
        <translation>Kopiert: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="82"/>
        <source>Measure: no surface under the mouse; click on the surface.</source>
        <translation>Messen: unter der Maus liegt keine Fläche; klicken Sie auf die Fläche.</translation>
    </message>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="123"/>
        <source>Edge %1: %2 mm long</source>
        <translation>Kante %1: %2 mm lang</translation>
    </message>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="131"/>
        <source>Edges %1 and %2 meet at vertex %3 at %4°</source>
        <translation>Kanten %1 und %2 treffen sich in Eckpunkt %3 unter %4°</translation>
    </message>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="143"/>
        <source>Measured: %1. Ctrl+C copies it.</source>
        <translation>Gemessen: %1. Ctrl+C kopiert es.</translation>
    </message>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="168"/>
        <source>Measure: first point picked; click the second.</source>
        <translation>Messen: erster Punkt gewählt; klicken Sie den zweiten.</translation>
    </message>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="187"/>
        <source>3D %1 mm, along the sheet %2 mm</source>
        <translation>3D %1 mm, entlang des Bogens %2 mm</translation>
    </message>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="188"/>
        <source>3D %1 mm (the points lie on different surfaces)</source>
        <translation>3D %1 mm (die Punkte liegen auf verschiedenen Flächen)</translation>
    </message>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="191"/>
        <source>Distance: %1. Ctrl+C copies it.</source>
        <translation>Abstand: %1. Ctrl+C kopiert ihn.</translation>
    </message>
</context>
<context>
    <name>devsurf::app::MoveDialog</name>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="43"/>
        <source>&amp;Translate</source>
        <translation>&amp;Verschieben</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="44"/>
        <source>&amp;Rotate</source>
        <translation>&amp;Drehen</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="45"/>
        <source>&amp;Keep developable</source>
        <translation>&amp;Abwickelbar halten</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="46"/>
        <source>Move or Rotate Vertices</source>
        <translation>Ecken verschieben oder drehen</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="52"/>
        <source>Translation</source>
        <translation>Verschiebung</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="55"/>
        <source>Offset (x, y, z):</source>
        <translation>Versatz (x, y, z):</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="58"/>
        <source>Rotation</source>
        <translation>Drehung</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="61"/>
        <source>Axis through (x, y, z):</source>
        <translation>Achse durch (x, y, z):</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="63"/>
        <source>Axis direction:</source>
        <translation>Achsrichtung:</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="68"/>
        <source>Angle:</source>
        <translation>Winkel:</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="76"/>
        <source>After the motion, run 10 solver iterations with the moved vertices held at their new positions and the pinned vertices where they are, so that the surface stays developable. The motion and the solve are one undo step; Esc cancels the solve and nothing moves. Off: only the exact motion.</source>
        <translation>Nach der Bewegung 10 Iterationen des Lösers ausführen, mit den bewegten Ecken an ihren neuen Positionen und den festgehaltenen Ecken an ihrem Ort, damit die Fläche abwickelbar bleibt. Bewegung und Lösen sind ein Rückgängig-Schritt; Esc bricht das Lösen ab, und nichts bewegt sich. Aus: nur die exakte Bewegung.</translation>
    </message>
</context>
<context>
    <name>devsurf::app::MoveVerticesReaction</name>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="382"/>
        <source>Translate or rotate the selected vertices with their neighbouring control points. Select vertices of one surface first.</source>
        <translation>Verschiebt oder dreht die ausgewählten Ecken samt benachbarten Kontrollpunkten. Wählen Sie zuerst Ecken einer Fläche aus.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="410"/>
        <source>Cannot rotate</source>
        <translation>Drehen nicht möglich</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="410"/>
        <source>Cannot move</source>
        <translation>Verschieben nicht möglich</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="419"/>
        <source>the vertices are moved</source>
        <translation>die Ecken werden bewegt</translation>
    </message>
</context>
<context>
    <name>devsurf::app::OpenReaction</name>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="34"/>
        <source>Open Project</source>
        <translation>Projekt öffnen</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="36"/>
        <source>DevSurf projects (*.devsurf)</source>
        <translation>DevSurf-Projekte (*.devsurf)</translation>
    </message>
</context>
<context>
    <name>devsurf::app::OpenRecentReaction</name>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="64"/>
        <source>No recent files</source>
        <translation>Keine zuletzt geöffneten Dateien</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="68"/>
        <source>Clear Recent Files</source>
        <translation>Liste leeren</translation>
    </message>
</context>
<context>
    <name>devsurf::app::PatchTreeModel</name>
    <message numerus="yes">
        <location filename="../app/gui/panels/patch_tree_model.cpp" line="120"/>
        <source>%n patch(es)</source>
        <translation>
            <numerusform>%n Flächenstück</numerusform>
            <numerusform>%n Flächenstücke</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/panels/patch_tree_model.cpp" line="129"/>
        <source>Patch %1</source>
        <translation>Flächenstück %1</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/patch_tree_model.cpp" line="133"/>
        <source>invalid labelling %1</source>
        <translation>ungültige Beschriftung %1</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/patch_tree_model.cpp" line="142"/>
        <source>Edge labels along the patch: %1</source>
        <translation>Kantenbeschriftung entlang des Flächenstücks: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/patch_tree_model.cpp" line="152"/>
        <source>Patch</source>
        <translation>Flächenstück</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/patch_tree_model.cpp" line="152"/>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
</context>
<context>
    <name>devsurf::app::PatternExportDialog</name>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="84"/>
        <source>DXF drawing (*.dxf)</source>
        <translation>DXF-Zeichnung (*.dxf)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="86"/>
        <source>SVG image (*.svg)</source>
        <translation>SVG-Bild (*.svg)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="88"/>
        <source>PDF document (*.pdf)</source>
        <translation>PDF-Dokument (*.pdf)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="90"/>
        <source>FOLD crease pattern (*.fold)</source>
        <translation>FOLD-Faltmuster (*.fold)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="98"/>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="345"/>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="353"/>
        <source>Export Cutting Pattern</source>
        <translation>Schnittmuster exportieren</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="102"/>
        <source>DXF (laser and plotter cutters)</source>
        <translation>DXF (Laser- und Plotterschneider)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="102"/>
        <source>SVG (vinyl and paper cutters)</source>
        <translation>SVG (Folien- und Papierschneider)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="103"/>
        <source>PDF (print at 1:1, tiled)</source>
        <translation>PDF (Druck 1:1, gekachelt)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="103"/>
        <source>FOLD (origami simulators)</source>
        <translation>FOLD (Origami-Simulatoren)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="104"/>
        <source>&amp;Format:</source>
        <translation>&amp;Format:</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="106"/>
        <source>&amp;Polylines</source>
        <translation>&amp;Polylinien</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="107"/>
        <source>S&amp;plines</source>
        <translation>S&amp;plines</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="114"/>
        <source>DXF &amp;R12 (for old cutter software)</source>
        <translation>DXF &amp;R12 (für alte Schneidsoftware)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="116"/>
        <source>Curves:</source>
        <translation>Kurven:</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="122"/>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="140"/>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="159"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="123"/>
        <source>&amp;Tolerance:</source>
        <translation>&amp;Toleranz:</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="126"/>
        <source>Cut</source>
        <translation>Schnitt</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="126"/>
        <source>Mountain</source>
        <translation>Berg</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="126"/>
        <source>Valley</source>
        <translation>Tal</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="127"/>
        <source>Crease</source>
        <translation>Falz</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="127"/>
        <source>Rulings (score)</source>
        <translation>Erzeugende (ritzen)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="127"/>
        <source>Seam</source>
        <translation>Naht</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="128"/>
        <source>Labels</source>
        <translation>Beschriftungen</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="136"/>
        <source>Layers:</source>
        <translation>Ebenen:</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="141"/>
        <source>as &amp;glue tabs</source>
        <translation>als &amp;Klebelaschen</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="146"/>
        <source>&amp;Seam allowance:</source>
        <translation>&amp;Nahtzugabe:</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="166"/>
        <source>S&amp;heet:</source>
        <translation>&amp;Bogen:</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="171"/>
        <source>A4</source>
        <translation>A4</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="171"/>
        <source>A3</source>
        <translation>A3</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="171"/>
        <source>Letter</source>
        <translation>Letter</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="172"/>
        <source>P&amp;aper (PDF):</source>
        <translation>P&amp;apier (PDF):</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="179"/>
        <source>Piece</source>
        <translation>Teil</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="179"/>
        <source>Sheet</source>
        <translation>Bogen</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="179"/>
        <source>Size (mm)</source>
        <translation>Größe (mm)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="180"/>
        <source>Area (mm²)</source>
        <translation>Fläche (mm²)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="180"/>
        <source>Isometry error (mm)</source>
        <translation>Isometriefehler (mm)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="181"/>
        <source>Fits sheet</source>
        <translation>Passt auf Bogen</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="181"/>
        <source>Overlaps</source>
        <translation>Überlappungen</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="185"/>
        <source>Fabrication report</source>
        <translation>Fertigungsbericht</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="192"/>
        <source>&amp;Export…</source>
        <translation>&amp;Exportieren…</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="303"/>
        <source>itself</source>
        <translation>sich selbst</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="310"/>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="315"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="311"/>
        <source>%1 × %2</source>
        <translation>%1 × %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="314"/>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="314"/>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pattern_export_dialog.cpp" line="320"/>
        <source>%n piece(s)</source>
        <translation>
            <numerusform>%n Teil</numerusform>
            <numerusform>%n Teile</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pattern_export_dialog.cpp" line="321"/>
        <source>%n sheet(s)</source>
        <translation>
            <numerusform>%n Bogen</numerusform>
            <numerusform>%n Bogen</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="323"/>
        <source>largest isometry error %1 mm</source>
        <translation>größter Isometriefehler %1 mm</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="343"/>
        <source>Some pieces overlap and cannot be cut as laid out. Export anyway?</source>
        <translation>Einige Teile überlappen sich und können so nicht geschnitten werden. Trotzdem exportieren?</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="344"/>
        <source>The pattern has problems (see the report). Export anyway?</source>
        <translation>Das Schnittmuster hat Probleme (siehe Bericht). Trotzdem exportieren?</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="378"/>
        <source>Writing the cutting pattern…</source>
        <translation>Das Schnittmuster wird geschrieben…</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="378"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="364"/>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="374"/>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="389"/>
        <source>Export failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
</context>
<context>
    <name>devsurf::app::PinVerticesReaction</name>
    <message>
        <location filename="../app/gui/reactions/pin_reactions.cpp" line="51"/>
        <source>Pin the selected vertices: the solver never moves them. Select vertices of one surface first.</source>
        <translation>Die gewählten Ecken festhalten: Der Löser bewegt sie nie. Wählen Sie zuerst Ecken einer Fläche.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pin_reactions.cpp" line="53"/>
        <source>Release the selected pinned vertices. Select vertices of one surface first.</source>
        <translation>Die gewählten festgehaltenen Ecken freigeben. Wählen Sie zuerst Ecken einer Fläche.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pin_reactions.cpp" line="58"/>
        <source>Pin the selected vertices: the solver never moves them.</source>
        <translation>Die gewählten Ecken festhalten: Der Löser bewegt sie nie.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pin_reactions.cpp" line="59"/>
        <source>Release the selected pinned vertices.</source>
        <translation>Die gewählten festgehaltenen Ecken freigeben.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pin_reactions.cpp" line="70"/>
        <source>Cannot pin the vertices</source>
        <translation>Die Ecken können nicht festgehalten werden</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pin_reactions.cpp" line="70"/>
        <source>Cannot unpin the vertices</source>
        <translation>Die Ecken können nicht freigegeben werden</translation>
    </message>
</context>
<context>
    <name>devsurf::app::PinsPanel</name>
    <message>
        <location filename="../app/gui/panels/pins_panel.cpp" line="22"/>
        <source>Unpin</source>
        <translation>Freigeben</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/pins_panel.cpp" line="26"/>
        <source>No vertex is pinned. Select vertices and choose Tools ▸ Pin Vertices (Ctrl+K): the solver then never moves them.</source>
        <translation>Keine Ecke ist festgehalten. Wählen Sie Ecken aus und dann Werkzeuge ▸ Ecken festhalten (Ctrl+K): Der Löser bewegt sie dann nie.</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/pins_panel.cpp" line="29"/>
        <source>The pinned vertices: the solver never moves them. Selecting a row selects its vertex in the views.</source>
        <translation>Die festgehaltenen Ecken: Der Löser bewegt sie nie. Eine Zeile auswählen wählt ihre Ecke in den Ansichten aus.</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/pins_panel.cpp" line="32"/>
        <source>Release the selected pinned vertices (one undo step).</source>
        <translation>Die ausgewählten festgehaltenen Ecken freigeben (ein Rückgängig-Schritt).</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/pins_panel.cpp" line="66"/>
        <source>Vertex %1</source>
        <translation>Ecke %1</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/pins_panel.cpp" line="67"/>
        <source>Surface %1, vertex %2</source>
        <translation>Fläche %1, Ecke %2</translation>
    </message>
</context>
<context>
    <name>devsurf::app::PrintPatternReaction</name>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="109"/>
        <source>Print Cutting Pattern</source>
        <translation>Schnittmuster drucken</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="114"/>
        <source>Printing failed</source>
        <translation>Drucken fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="115"/>
        <source>The pages could not be sent to the printer.</source>
        <translation>Die Seiten konnten nicht an den Drucker gesendet werden.</translation>
    </message>
</context>
<context>
    <name>devsurf::app::PrintPreviewReaction</name>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="135"/>
        <source>Print Preview: Cutting Pattern</source>
        <translation>Druckvorschau: Schnittmuster</translation>
    </message>
</context>
<context>
    <name>devsurf::app::PropertiesPanel</name>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="28"/>
        <source>degree %1, C%2, %3 intervals</source>
        <translation>Grad %1, C%2, %3 Intervalle</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="152"/>
        <source>&lt;b&gt;Vertex %1&lt;/b&gt;</source>
        <translation>&lt;b&gt;Ecke %1&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="164"/>
        <source>&lt;b&gt;Edge %1&lt;/b&gt; from vertex %2 to vertex %3&lt;br&gt;</source>
        <translation>&lt;b&gt;Kante %1&lt;/b&gt; von Ecke %2 zu Ecke %3&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="126"/>
        <source>Nothing selected.&lt;br&gt;%1, %2.&lt;br&gt;&lt;i&gt;Click a vertex, edge or patch to select it; Shift-click adds to the selection.&lt;/i&gt;</source>
        <translation>Nichts ausgewählt.&lt;br&gt;%1, %2.&lt;br&gt;&lt;i&gt;Klicken Sie auf eine Ecke, Kante oder ein Flächenstück, um es auszuwählen; Umschalt-Klick erweitert die Auswahl.&lt;/i&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="39"/>
        <source>A crease between patches %1 (left) and %2 (right); condition: %3.&lt;br&gt;</source>
        <translation>Ein Falz zwischen den Flächenstücken %1 (links) und %2 (rechts); Bedingung: %3.&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="51"/>
        <source>Mountain fold of %1° (up to %2°).</source>
        <translation>Bergfalte um %1° (bis %2°).</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="55"/>
        <source>Valley fold of %1° (up to %2°).</source>
        <translation>Talfalte um %1° (bis %2°).</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="59"/>
        <source>Not folded.</source>
        <translation>Nicht gefaltet.</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="80"/>
        <source>&lt;b&gt;Pinned&lt;/b&gt;: the solver never moves this vertex. Tools ▸ Unpin Vertices (Ctrl+Shift+K) releases it.</source>
        <translation>&lt;b&gt;Festgehalten&lt;/b&gt;: Der Löser bewegt diese Ecke nie. Werkzeuge ▸ Ecken freigeben (Ctrl+Shift+K) gibt sie frei.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/panels/properties_panel.cpp" line="128"/>
        <location filename="../app/gui/panels/properties_panel.cpp" line="138"/>
        <source>%n patch(es)</source>
        <translation>
            <numerusform>%n Flächenstück</numerusform>
            <numerusform>%n Flächenstücke</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/panels/properties_panel.cpp" line="129"/>
        <source>%n control point(s)</source>
        <translation>
            <numerusform>%n Kontrollpunkt</numerusform>
            <numerusform>%n Kontrollpunkte</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="136"/>
        <source>Selected: %1, %2, %3.</source>
        <translation>Ausgewählt: %1, %2, %3.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/panels/properties_panel.cpp" line="137"/>
        <source>%n vertex(es)</source>
        <translation>
            <numerusform>%n Ecke</numerusform>
            <numerusform>%n Ecken</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/panels/properties_panel.cpp" line="137"/>
        <source>%n edge(s)</source>
        <translation>
            <numerusform>%n Kante</numerusform>
            <numerusform>%n Kanten</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/panels/properties_panel.cpp" line="169"/>
        <source>Spline curve (S), %1, %n control point(s).&lt;br&gt;</source>
        <translation>
            <numerusform>Spline-Kurve (S), %1, %n Kontrollpunkt.&lt;br&gt;</numerusform>
            <numerusform>Spline-Kurve (S), %1, %n Kontrollpunkte.&lt;br&gt;</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="175"/>
        <source>A boundary curve of patch %1.</source>
        <translation>Eine Randkurve des Flächenstücks %1.</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="179"/>
        <source>Ruling (R), a straight segment of length %1 mm.</source>
        <translation>Erzeugende (R), eine Strecke der Länge %1 mm.</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="186"/>
        <source>Smooth between patches %1 and %2: the surface stays smooth across it.</source>
        <translation>Glatt zwischen den Flächenstücken %1 und %2: Die Fläche bleibt über sie hinweg glatt.</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="188"/>
        <source>Sharp between patches %1 and %2: the surface may fold along it.</source>
        <translation>Scharf zwischen den Flächenstücken %1 und %2: Die Fläche darf entlang ihr falten.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/panels/properties_panel.cpp" line="198"/>
        <source>&lt;b&gt;Patch %1&lt;/b&gt;: %2&lt;br&gt;Edge labels along the patch: %3&lt;br&gt;%n corner(s).</source>
        <translation>
            <numerusform>&lt;b&gt;Flächenstück %1&lt;/b&gt;: %2&lt;br&gt;Kantenbeschriftung entlang des Flächenstücks: %3&lt;br&gt;%n Ecke.</numerusform>
            <numerusform>&lt;b&gt;Flächenstück %1&lt;/b&gt;: %2&lt;br&gt;Kantenbeschriftung entlang des Flächenstücks: %3&lt;br&gt;%n Ecken.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="237"/>
        <source>Cannot move</source>
        <translation>Verschieben nicht möglich</translation>
    </message>
</context>
<context>
    <name>devsurf::app::RefineCurvesReaction</name>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="360"/>
        <source>Double the spline intervals of the selected curve and of all curves joined to it through strips; the shape stays the same. Select one spline edge or strip first.</source>
        <translation>Verdoppelt die Spline-Intervalle der ausgewählten Kurve und aller über Streifen mit ihr verbundenen Kurven; die Form bleibt gleich. Wählen Sie zuerst eine Splinekante oder einen Streifen aus.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="370"/>
        <source>Cannot refine</source>
        <translation>Verfeinern nicht möglich</translation>
    </message>
</context>
<context>
    <name>devsurf::app::RelabelEdgeReaction</name>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="123"/>
        <source>Cannot relabel: %1</source>
        <translation>Kennzeichnung kann nicht geändert werden: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="127"/>
        <source>Turn the selected edges from rulings (R) into spline curves (S) or back. Select edges of one surface first.</source>
        <translation>Macht die ausgewählten Kanten von Erzeugenden (R) zu Splinekurven (S) oder umgekehrt. Wählen Sie zuerst Kanten einer Fläche aus.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="134"/>
        <source>Cannot relabel</source>
        <translation>Kennzeichnung kann nicht geändert werden</translation>
    </message>
</context>
<context>
    <name>devsurf::app::RemoveReferenceCurvesReaction</name>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="150"/>
        <source>Cannot remove the reference curves</source>
        <translation>Die Referenzkurven können nicht entfernt werden</translation>
    </message>
</context>
<context>
    <name>devsurf::app::RemoveReferenceShapesReaction</name>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="154"/>
        <source>Cannot remove the reference shapes</source>
        <translation>Die Referenzformen können nicht entfernt werden</translation>
    </message>
</context>
<context>
    <name>devsurf::app::RemoveRulingReaction</name>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="298"/>
        <source>Remove the selected ruling between two strips, merging them into one strip whose curves join theirs. Select one ruling between two strips first.</source>
        <translation>Die ausgewählte Erzeugende zwischen zwei Streifen entfernen und beide zu einem Streifen verschmelzen, dessen Kurven ihre fortsetzen. Wählen Sie zuerst eine Erzeugende zwischen zwei Streifen.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="312"/>
        <source>Cannot remove the ruling</source>
        <translation>Die Erzeugende kann nicht entfernt werden</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="322"/>
        <source>Ruling %1 removed: its two strips are one strip, the shape unchanged.</source>
        <translation>Erzeugende %1 entfernt: ihre beiden Streifen sind ein Streifen, die Form unverändert.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="324"/>
        <source>Ruling %1 removed: its two strips are one strip, up to %2 from where they were; Tools ▸ Solve makes it developable again if it is not.</source>
        <translation>Erzeugende %1 entfernt: ihre beiden Streifen sind ein Streifen, bis zu %2 von ihrer vorherigen Lage; Werkzeuge ▸ Lösen macht ihn wieder abwickelbar, falls nötig.</translation>
    </message>
</context>
<context>
    <name>devsurf::app::RotateTool</name>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="29"/>
        <source>Rotate needs two or more vertices that are not pinned: select them, then press on one of them and move the mouse sideways.</source>
        <translation>Drehen braucht zwei oder mehr nicht festgehaltene Ecken: Wählen Sie sie aus, drücken Sie dann auf eine von ihnen und bewegen Sie die Maus seitwärts.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/rotate_tool.cpp" line="49"/>
        <source>Rotate %n vertices %1: move the mouse sideways, %2° per pixel.</source>
        <translation>
            <numerusform>%n Ecke %1 drehen: Maus seitwärts bewegen, %2° pro Pixel.</numerusform>
            <numerusform>%n Ecken %1 drehen: Maus seitwärts bewegen, %2° pro Pixel.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="77"/>
        <source>about the X axis through their centroid</source>
        <translation>um die X-Achse durch ihren Schwerpunkt</translation>
    </message>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="79"/>
        <source>about the Y axis through their centroid</source>
        <translation>um die Y-Achse durch ihren Schwerpunkt</translation>
    </message>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="81"/>
        <source>about the Z axis through their centroid</source>
        <translation>um die Z-Achse durch ihren Schwerpunkt</translation>
    </message>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="85"/>
        <source>about the view axis through their centroid</source>
        <translation>um die Blickachse durch ihren Schwerpunkt</translation>
    </message>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="86"/>
        <source>about the vertical axis (Z) through their centroid</source>
        <translation>um die senkrechte Achse (Z) durch ihren Schwerpunkt</translation>
    </message>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="90"/>
        <source>Rotate tool: select two or more vertices, press on one of them in the 3D view and move the mouse sideways (%1° per pixel). Esc cancels a rotation.</source>
        <translation>Drehwerkzeug: Wählen Sie zwei oder mehr Ecken aus, drücken Sie in der 3D-Ansicht auf eine von ihnen und bewegen Sie die Maus seitwärts (%1° pro Pixel). Esc bricht eine Drehung ab.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/rotate_tool.cpp" line="96"/>
        <source>Rotating %n vertices by %1° %2. Release to finish, Esc cancels.</source>
        <translation>
            <numerusform>%n Ecke wird um %1° %2 gedreht. Loslassen beendet, Esc bricht ab.</numerusform>
            <numerusform>%n Ecken werden um %1° %2 gedreht. Loslassen beendet, Esc bricht ab.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/rotate_tool.cpp" line="102"/>
        <source>Rotate %n vertices</source>
        <translation>
            <numerusform>%n Ecke drehen</numerusform>
            <numerusform>%n Ecken drehen</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="106"/>
        <source>Rotation cancelled; the design is as it was.</source>
        <translation>Drehung abgebrochen; der Entwurf ist wie zuvor.</translation>
    </message>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="110"/>
        <source>Rotation stopped: %1 The design is as it was.</source>
        <translation>Drehung angehalten: %1 Der Entwurf ist wie zuvor.</translation>
    </message>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="114"/>
        <source>Rotation stopped: the design changed during the rotation.</source>
        <translation>Drehung angehalten: Der Entwurf hat sich während der Drehung geändert.</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ShapeExportDialog</name>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="35"/>
        <source>The design has no surface to export.</source>
        <translation>Der Entwurf hat keine Fläche, die exportiert werden könnte.</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="37"/>
        <source>Patch %1 of surface %2 cannot be written as an exact surface.</source>
        <translation>Flächenstück %1 der Fläche %2 kann nicht als exakte Fläche geschrieben werden.</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="42"/>
        <source>The shape could not be translated into this format. Try another format.</source>
        <translation>Die Form ließ sich nicht in dieses Format übertragen. Versuchen Sie ein anderes Format.</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="55"/>
        <location filename="../app/gui/shape_export_dialog.cpp" line="130"/>
        <location filename="../app/gui/shape_export_dialog.cpp" line="187"/>
        <location filename="../app/gui/shape_export_dialog.cpp" line="213"/>
        <source>Export 3D Shape</source>
        <translation>3D-Form exportieren</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="58"/>
        <source>STEP AP242: exact surfaces</source>
        <translation>STEP AP242: exakte Flächen</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="58"/>
        <source>STEP AP214: exact surfaces</source>
        <translation>STEP AP214: exakte Flächen</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="59"/>
        <source>IGES: exact surfaces</source>
        <translation>IGES: exakte Flächen</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="59"/>
        <source>OBJ mesh: a group per patch</source>
        <translation>OBJ-Netz: eine Gruppe je Flächenstück</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="60"/>
        <source>STL mesh (binary)</source>
        <translation>STL-Netz (binär)</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="60"/>
        <source>PLY mesh (binary)</source>
        <translation>PLY-Netz (binär)</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="67"/>
        <location filename="../app/gui/shape_export_dialog.cpp" line="74"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="68"/>
        <source>How far the mesh&apos;s triangles may stray from the exact surface.</source>
        <translation>Wie weit die Dreiecke des Netzes von der exakten Fläche abweichen dürfen.</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="75"/>
        <source>none (the surface)</source>
        <translation>keine (die Fläche)</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="77"/>
        <source>A sheet of this thickness for 3D printing: both sides offset by half of it, the rim closed.</source>
        <translation>Eine Platte dieser Dicke für den 3D-Druck: beide Seiten um die Hälfte versetzt, der Rand geschlossen.</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="83"/>
        <source>&amp;Format:</source>
        <translation>&amp;Format:</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="84"/>
        <source>Chord &amp;tolerance:</source>
        <translation>Sehnen&amp;toleranz:</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="85"/>
        <source>T&amp;hickness:</source>
        <translation>&amp;Dicke:</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="87"/>
        <source>&amp;Export…</source>
        <translation>&amp;Exportieren…</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="120"/>
        <source>A triangle mesh for renderers, slicers and mesh tools; watertight wherever the design is.</source>
        <translation>Ein Dreiecksnetz für Renderer, Slicer und Netzwerkzeuge; wasserdicht überall dort, wo der Entwurf es ist.</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="122"/>
        <source>Every patch as its exact B-spline surface, sewn into one shell per surface, in millimetres, faces named after their patches.</source>
        <translation>Jedes Flächenstück als seine exakte B-Spline-Fläche, je Fläche zu einer Schale vernäht, in Millimetern, die Flächen nach ihren Flächenstücken benannt.</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="131"/>
        <source>%1 files (*.%2)</source>
        <translation>%1-Dateien (*.%2)</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="141"/>
        <location filename="../app/gui/shape_export_dialog.cpp" line="149"/>
        <location filename="../app/gui/shape_export_dialog.cpp" line="152"/>
        <location filename="../app/gui/shape_export_dialog.cpp" line="154"/>
        <source>Export failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="160"/>
        <location filename="../app/gui/shape_export_dialog.cpp" line="202"/>
        <source>Writing the 3D shape…</source>
        <translation>Die 3D-Form wird geschrieben…</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="160"/>
        <location filename="../app/gui/shape_export_dialog.cpp" line="202"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="178"/>
        <source>surface %1, edge %2 (%3 mm apart)</source>
        <translation>Fläche %1, Kante %2 (%3 mm auseinander)</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="184"/>
        <source>faces: %1, shells: %2</source>
        <translation>Flächen: %1, Schalen: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="188"/>
        <source>The shape was written, but some patches could not be sewn together and stay apart in the file: %1.</source>
        <translation>Die Form wurde geschrieben, aber einige Flächenstücke ließen sich nicht vernähen und bleiben in der Datei getrennt: %1.</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="211"/>
        <source>triangles: %1</source>
        <translation>Dreiecke: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="214"/>
        <source>The mesh was written with %1 samples per curve interval, the most DevSurf writes, and is coarser than the tolerance asked for.</source>
        <translation>Das Netz wurde mit %1 Abtastpunkten je Kurvenintervall geschrieben, dem Höchstwert von DevSurf, und ist gröber als die verlangte Toleranz.</translation>
    </message>
</context>
<context>
    <name>devsurf::app::SheetShapeDialog</name>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="52"/>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="53"/>
        <source>Choose…</source>
        <translation>Auswählen…</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="54"/>
        <source>None</source>
        <translation>Keine</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="55"/>
        <source>As They Lie</source>
        <translation>Wie sie liegen</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="58"/>
        <source>Sheet Shape</source>
        <translation>Bogenform</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="61"/>
        <source>Free: the development as it is</source>
        <translation>Frei: die Abwicklung, wie sie ist</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="63"/>
        <source>Rectangle</source>
        <translation>Rechteck</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="64"/>
        <source>Disk</source>
        <translation>Kreisscheibe</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="65"/>
        <source>Annulus</source>
        <translation>Kreisring</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="66"/>
        <source>Outline of a drawing</source>
        <translation>Umriss einer Zeichnung</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="77"/>
        <source>The closed curves of a DXF, SVG, STEP or IGES file, seen from above: the largest is the sheet&apos;s boundary, the others its holes.</source>
        <translation>Die geschlossenen Kurven einer DXF-, SVG-, STEP- oder IGES-Datei, von oben gesehen: die größte ist der Rand des Bogens, die anderen seine Löcher.</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="95"/>
        <source>The sheet the surface is folded from. Every solve and drag keeps the surface isometric to its development; with a shape, the development may change inside it, its boundary on the shape&apos;s and its corners at the shape&apos;s corners.</source>
        <translation>Der Bogen, aus dem die Fläche gefaltet wird. Jedes Lösen und Ziehen hält die Fläche isometrisch zu ihrer Abwicklung; mit einer Form darf sich die Abwicklung innerhalb der Form ändern, ihr Rand liegt auf dem Rand der Form und ihre Ecken auf deren Ecken.</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="102"/>
        <source>Shape:</source>
        <translation>Form:</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="103"/>
        <source>Width:</source>
        <translation>Breite:</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="104"/>
        <source>Height:</source>
        <translation>Höhe:</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="105"/>
        <source>Radius:</source>
        <translation>Radius:</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="106"/>
        <source>Inner radius:</source>
        <translation>Innenradius:</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="110"/>
        <source>Outline:</source>
        <translation>Umriss:</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="122"/>
        <source>Curves drawn in the sheet for the creases to follow: every curve of a DXF, SVG, STEP or IGES file, seen from above, in the sheet&apos;s frame (a rectangle from its corner at 0,0; circles centred at 0,0; an outline in its own drawing&apos;s coordinates). A crease lying near a curve keeps its development on it.</source>
        <translation>In den Bogen gezeichnete Kurven, denen die Falze folgen: jede Kurve einer DXF-, SVG-, STEP- oder IGES-Datei, von oben gesehen, im Rahmen des Bogens (ein Rechteck ab seiner Ecke bei 0,0; Kreise um 0,0; ein Umriss in den Koordinaten seiner eigenen Zeichnung). Ein Falz nahe einer Kurve hält seine Abwicklung auf ihr.</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="127"/>
        <source>No curves: the creases move freely inside the sheet.</source>
        <translation>Keine Kurven: Die Falze bewegen sich frei im Bogen.</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="130"/>
        <source>Hold every crease on the curve it lies on in the sheet now: the crease pattern stays as it is while the rulings move in the sheet, so the design folds along its own creases.</source>
        <translation>Jeden Falz auf der Kurve halten, auf der er jetzt im Bogen liegt: Das Falzmuster bleibt, wie es ist, während sich die Erzeugenden im Bogen bewegen, so faltet sich der Entwurf entlang seiner eigenen Falze.</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="138"/>
        <source>Crease curves:</source>
        <translation>Falzkurven:</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="149"/>
        <source>Sheet Outline</source>
        <translation>Umriss des Bogens</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="150"/>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="160"/>
        <source>Drawings (*.dxf *.svg *.step *.stp *.iges *.igs)</source>
        <translation>Zeichnungen (*.dxf *.svg *.step *.stp *.iges *.igs)</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="159"/>
        <source>Crease Curves</source>
        <translation>Falzkurven</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="174"/>
        <source>The surface has no crease to hold.</source>
        <translation>Die Fläche hat keinen Falz, der gehalten werden könnte.</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="238"/>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="296"/>
        <source>%1 cannot be read as a drawing: choose a DXF, SVG, STEP or IGES file.</source>
        <translation>%1 kann nicht als Zeichnung gelesen werden: wählen Sie eine DXF-, SVG-, STEP- oder IGES-Datei.</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="241"/>
        <source>%1 holds no closed curve enclosing an area to be the sheet&apos;s outline.</source>
        <translation>%1 enthält keine geschlossene Kurve, die eine Fläche umschließt und den Umriss des Bogens bilden könnte.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="246"/>
        <source>%1: %n closed curve(s)</source>
        <translation>
            <numerusform>%1: %n geschlossene Kurve</numerusform>
            <numerusform>%1: %n geschlossene Kurven</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="328"/>
        <source>the creases as they lie: %n curve(s)</source>
        <translation>
            <numerusform>die Falze, wie sie liegen: %n Kurve</numerusform>
            <numerusform>die Falze, wie sie liegen: %n Kurven</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="338"/>
        <source>%1; no crease lies near them (within half its length, no other crease nearer), so they are not used</source>
        <translation>%1; kein Falz liegt nahe bei ihnen (innerhalb seiner halben Länge, ohne näheren anderen Falz), daher werden sie nicht verwendet</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="73"/>
        <source>none chosen</source>
        <translation>keiner gewählt</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="74"/>
        <source>%n closed curve(s)</source>
        <translation>
            <numerusform>%n geschlossene Kurve</numerusform>
            <numerusform>%n geschlossene Kurven</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="298"/>
        <source>%1 holds no curve for the creases to follow.</source>
        <translation>%1 enthält keine Kurve, der die Falze folgen könnten.</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="322"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="325"/>
        <source>%n curve(s)</source>
        <translation>
            <numerusform>%n Kurve</numerusform>
            <numerusform>%n Kurven</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="330"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="332"/>
        <source>%1, used with a shape only</source>
        <translation>%1, nur mit einer Form verwendet</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="345"/>
        <source>%1, holding %n crease(s)</source>
        <translation>
            <numerusform>%1, hält %n Falz</numerusform>
            <numerusform>%1, hält %n Falze</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="366"/>
        <source>The development covers %1 cm² and is held as it is.</source>
        <translation>Die Abwicklung bedeckt %1 cm² und wird gehalten, wie sie ist.</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="373"/>
        <source>Choose a drawing whose closed curves are the sheet&apos;s outline.</source>
        <translation>Wählen Sie eine Zeichnung, deren geschlossene Kurven den Umriss des Bogens bilden.</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="382"/>
        <source>The outline has no closed curve enclosing an area.</source>
        <translation>Der Umriss hat keine geschlossene Kurve, die eine Fläche umschließt.</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="383"/>
        <source>The inner radius must be smaller than the radius.</source>
        <translation>Der Innenradius muss kleiner als der Radius sein.</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="394"/>
        <source>The development (%1 cm²) is larger than this sheet (%2 cm²): no solve can fold the design from it.</source>
        <translation>Die Abwicklung (%1 cm²) ist größer als dieser Bogen (%2 cm²): kein Lösen kann die Form daraus falten.</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="403"/>
        <source>The development (%1 cm²) fits this sheet (%2 cm²): its boundary lies on the sheet&apos;s.</source>
        <translation>Die Abwicklung (%1 cm²) passt auf diesen Bogen (%2 cm²): ihr Rand liegt auf dem des Bogens.</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="407"/>
        <source>The development covers %1 cm² of this sheet&apos;s %2 cm²; its boundary is up to %3 mm from the sheet&apos;s, and the next Solve moves it onto the sheet.</source>
        <translation>Die Abwicklung bedeckt %1 cm² der %2 cm² dieses Bogens; ihr Rand liegt bis zu %3 mm vom Rand des Bogens entfernt, und das nächste Lösen legt ihn auf den Bogen.</translation>
    </message>
</context>
<context>
    <name>devsurf::app::SheetShapeReaction</name>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="61"/>
        <source>%1 closes around: it is folded from a cylinder of radius %2 mm, its development read modulo the cylinder&apos;s circumference, and no flat sheet shape applies.</source>
        <translation>%1 schließt sich ringsum: es ist aus einem Zylinder mit Radius %2 mm gefaltet, seine Abwicklung wird modulo des Zylinderumfangs gelesen, und keine ebene Blattform ist anwendbar.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="126"/>
        <source>Choose the sheet the surface is folded from: its development as it is, or a rectangle, disk or annulus its development stays inside.</source>
        <translation>Den Bogen wählen, aus dem die Fläche gefaltet wird: ihre Abwicklung, wie sie ist, oder ein Rechteck, eine Kreisscheibe oder ein Kreisring, in dem ihre Abwicklung bleibt.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="128"/>
        <source>Choose the sheet of a surface: select something on one surface first.</source>
        <translation>Den Bogen einer Fläche wählen: zuerst etwas auf einer Fläche auswählen.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="141"/>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="166"/>
        <source>Cannot hold the sheet</source>
        <translation>Der Bogen kann nicht festgehalten werden</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="182"/>
        <source>Set Sheet Shape</source>
        <translation>Bogenform festlegen</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="184"/>
        <source>Cannot set the sheet shape</source>
        <translation>Die Bogenform kann nicht festgelegt werden</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="189"/>
        <source>The development&apos;s creases are up to %1 mm from their curves, its boundary up to %2 mm from the sheet&apos;s: Solve moves them there.</source>
        <translation>Die Falze der Abwicklung liegen bis zu %1 mm von ihren Kurven entfernt, ihr Rand bis zu %2 mm vom Rand des Bogens: Lösen bringt sie dorthin.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="194"/>
        <source>The development&apos;s boundary is up to %1 mm from the sheet&apos;s: Solve moves it onto the sheet.</source>
        <translation>Der Rand der Abwicklung liegt bis zu %1 mm vom Rand des Bogens entfernt: Lösen legt ihn auf den Bogen.</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ShortcutsDialog</name>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="79"/>
        <source>Keyboard Shortcuts</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="81"/>
        <source>Keys</source>
        <translation>Tasten</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="81"/>
        <source>Command</source>
        <translation>Befehl</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="92"/>
        <source>Click</source>
        <translation>Klick</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="92"/>
        <source>Select a vertex, edge or patch (empty space clears)</source>
        <translation>Ecke, Kante oder Flächenstück auswählen (leere Stelle hebt die Auswahl auf)</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="93"/>
        <source>Shift+Click</source>
        <translation>Umschalt+Klick</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="93"/>
        <source>Add to or remove from the selection</source>
        <translation>Zur Auswahl hinzufügen oder daraus entfernen</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="94"/>
        <source>Ctrl+Drag</source>
        <translation>Strg+Ziehen</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="94"/>
        <source>Select the vertices in a rectangle (with Shift: add them)</source>
        <translation>Ecken in einem Rechteck auswählen (mit Umschalt: hinzufügen)</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="95"/>
        <source>Left drag</source>
        <translation>Ziehen mit links</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="95"/>
        <source>3D view: rotate; development view: pan</source>
        <translation>3D-Ansicht: drehen; Abwicklung: verschieben</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="96"/>
        <source>Middle drag</source>
        <translation>Ziehen mit Mitte</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="96"/>
        <source>Pan</source>
        <translation>Verschieben</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="97"/>
        <source>Wheel or right drag</source>
        <translation>Mausrad oder Ziehen mit rechts</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="97"/>
        <source>Zoom</source>
        <translation>Zoomen</translation>
    </message>
</context>
<context>
    <name>devsurf::app::SmoothRulingsReaction</name>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="136"/>
        <source>Smooth: the solver keeps the surface smooth across the selected rulings (both patches share the tangent plane).</source>
        <translation>Glatt: Der Löser hält die Fläche über die ausgewählten Erzeugenden hinweg glatt (beide Flächenstücke teilen die Tangentialebene).</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="138"/>
        <source>Sharp: the surface may fold along the selected rulings.</source>
        <translation>Scharf: Die Fläche darf entlang der ausgewählten Erzeugenden falten.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="140"/>
        <source>Select rulings between two patches of one surface first.</source>
        <translation>Wählen Sie zuerst Erzeugende zwischen zwei Flächenstücken einer Fläche aus.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="178"/>
        <source>&amp;Smooth Rulings</source>
        <translation>&amp;Glatte Erzeugende</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="181"/>
        <source>S&amp;harp Rulings</source>
        <translation>&amp;Scharfe Erzeugende</translation>
    </message>
</context>
<context>
    <name>devsurf::app::SolveController</name>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="97"/>
        <source>There is nothing to solve.</source>
        <translation>Es gibt nichts zu lösen.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="121"/>
        <source>%1: there is nothing to solve; nothing changed.</source>
        <translation>%1: Es gibt nichts zu lösen; nichts wurde geändert.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="194"/>
        <source>%1 cancelled; the design is unchanged.</source>
        <translation>%1 abgebrochen; der Entwurf ist unverändert.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="195"/>
        <source>%1 cancelled: %2; the design is unchanged.</source>
        <translation>%1 abgebrochen: %2; der Entwurf ist unverändert.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="198"/>
        <source>%1 cancelled; nothing moved.</source>
        <translation>%1 abgebrochen; nichts wurde bewegt.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="199"/>
        <source>%1 cancelled: %2; nothing moved.</source>
        <translation>%1 abgebrochen: %2; nichts wurde bewegt.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="201"/>
        <source>Solve cancelled; the design is unchanged.</source>
        <translation>Lösen abgebrochen; der Entwurf ist unverändert.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="202"/>
        <source>Solve cancelled: %1; the design is unchanged.</source>
        <translation>Lösen abgebrochen: %1; der Entwurf ist unverändert.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_controller.cpp" line="208"/>
        <source>Check the shape: %n patch(es) fold over onto themselves (%1); undo, or pin or move differently.</source>
        <translation>
            <numerusform>Form prüfen: %n Flächenstück faltet sich auf sich selbst zurück (%1); rückgängig machen oder anders fixieren oder bewegen.</numerusform>
            <numerusform>Form prüfen: %n Flächenstücke falten sich auf sich selbst zurück (%1); rückgängig machen oder anders fixieren oder bewegen.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_controller.cpp" line="215"/>
        <source>Check the shape: the development overlaps itself at %n patch(es) (%1); undo, or pin or move differently.</source>
        <translation>
            <numerusform>Form prüfen: die Abwicklung überlappt sich selbst an %n Flächenstück (%1); rückgängig machen oder anders fixieren oder bewegen.</numerusform>
            <numerusform>Form prüfen: die Abwicklung überlappt sich selbst an %n Flächenstücken (%1); rückgängig machen oder anders fixieren oder bewegen.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="225"/>
        <source>%1 failed: %2 The design is unchanged.</source>
        <translation>%1 fehlgeschlagen: %2 Der Entwurf ist unverändert.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="227"/>
        <source>%1 failed: %2 Nothing moved.</source>
        <translation>%1 fehlgeschlagen: %2 Nichts wurde bewegt.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="256"/>
        <source>the design changed</source>
        <translation>der Entwurf hat sich geändert</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="395"/>
        <source>The sheet held the moved vertices back by up to %1 mm.</source>
        <translation>Der Bogen hielt die bewegten Ecken um bis zu %1 mm zurück.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="23"/>
        <source>it stopped before a degenerate shape</source>
        <translation>es hielt vor einer entarteten Form an</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="26"/>
        <source>no convergence, residual %1</source>
        <translation>keine Konvergenz, Residuum %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_report_text.cpp" line="29"/>
        <location filename="../app/gui/solve_report_text.cpp" line="58"/>
        <source>folded over in %n place(s)</source>
        <translation>
            <numerusform>an %n Stelle zurückgefaltet</numerusform>
            <numerusform>an %n Stellen zurückgefaltet</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="32"/>
        <source>a development overlapping itself</source>
        <translation>eine sich selbst überlappende Abwicklung</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="35"/>
        <source>collapsed strips</source>
        <translation>zusammengefallene Streifen</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="38"/>
        <source>a shape too degenerate to measure</source>
        <translation>eine zum Messen zu entartete Form</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="47"/>
        <source>did not reach the tolerance (residual %1; patch %2 sampled %3 from developable)</source>
        <translation>Toleranz nicht erreicht (Residuum %1; Flächenstück %2 abgetastet %3 von abwickelbar entfernt)</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="54"/>
        <source>left its kept sheet by %1 mm</source>
        <translation>um %1 mm vom gehaltenen Bogen abgewichen</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_report_text.cpp" line="61"/>
        <source>left a development overlapping itself at %n patch(es)</source>
        <translation>
            <numerusform>Abwicklung an %n Flächenstück mit sich selbst überlappend</numerusform>
            <numerusform>Abwicklung an %n Flächenstücken mit sich selbst überlappend</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="68"/>
        <source>would stretch its sheet by %1 % to lie flat</source>
        <translation>flach ausgelegt um %1 % gedehnt</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="70"/>
        <source>would not lie flat as one sheet</source>
        <translation>nicht als ein Bogen flach auslegbar</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="73"/>
        <source>ended not developable</source>
        <translation>nicht abwickelbar geendet</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="101"/>
        <source>Surface %1</source>
        <translation>Fläche %1</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="106"/>
        <source>The solve was cancelled.</source>
        <translation>Das Lösen wurde abgebrochen.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="109"/>
        <source>%1 cannot be solved: %2</source>
        <translation>%1 kann nicht gelöst werden: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="110"/>
        <source>%1 cannot be solved.</source>
        <translation>%1 kann nicht gelöst werden.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="114"/>
        <source>The drag target of vertex %1 is not a finite point.</source>
        <translation>Das Ziel der gezogenen Ecke %1 ist kein endlicher Punkt.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="115"/>
        <source>The drag target of control point %1 of edge %2 is not a finite point.</source>
        <translation>Das Ziel des gezogenen Kontrollpunkts %1 der Kante %2 ist kein endlicher Punkt.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="121"/>
        <source>%1 could not be solved: the linear system could not be factorised.</source>
        <translation>%1 konnte nicht gelöst werden: das lineare Gleichungssystem ließ sich nicht faktorisieren.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="123"/>
        <source>%1 could not be solved: an iteration gave values that are not finite.</source>
        <translation>%1 konnte nicht gelöst werden: eine Iteration ergab Werte, die nicht endlich sind.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="127"/>
        <source>%1 could not be solved: the solver produced a value that is not finite.</source>
        <translation>%1 konnte nicht gelöst werden: der Löser lieferte einen Wert, der nicht endlich ist.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="133"/>
        <source>(Solver: %1)</source>
        <translation>(Löser: %1)</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="151"/>
        <source>Cancelled; the design is unchanged.</source>
        <translation>Abgebrochen; der Entwurf ist unverändert.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="155"/>
        <source>Failed: %1</source>
        <translation>Fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="169"/>
        <source>converged</source>
        <translation>konvergiert</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="173"/>
        <source>tolerance reached</source>
        <translation>Toleranz erreicht</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="176"/>
        <source>stopped after %1 iterations, the residual no longer falling</source>
        <translation>nach %1 Iterationen beendet, da das Residuum nicht mehr fiel</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="179"/>
        <source>iteration limit reached</source>
        <translation>Iterationsgrenze erreicht</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="187"/>
        <source>failed</source>
        <translation>fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="195"/>
        <source>; left as it was, since solving made it less developable (%1 → %2)</source>
        <translation>; unverändert gelassen, da das Lösen sie weniger abwickelbar machte (%1 → %2)</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="201"/>
        <source>; settled a second time, since the first settling after the release did not converge</source>
        <translation>; ein zweites Mal zur Ruhe gebracht, da das erste Zur-Ruhe-Kommen nach dem Loslassen nicht konvergierte</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="205"/>
        <source>; keeping lengths failed (%1), so the drag was replayed letting the sheet stretch</source>
        <translation>; das Beibehalten der Längen schlug fehl (%1), daher wurde das Ziehen mit Dehnen des Blatts wiederholt</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="214"/>
        <source>followed %1 % of the drag and held back %2 mm, since the whole drag %3: the design stays at its last developable state</source>
        <translation>folgt %1 % des Ziehens und bleibt %2 mm zurück, denn das ganze Ziehen hätte so geendet: %3; der Entwurf bleibt in seinem letzten abwickelbaren Zustand</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="220"/>
        <source>not applied, since the motion %1: the design stays as it was</source>
        <translation>nicht angewendet, denn die Bewegung hätte so geendet: %1; der Entwurf bleibt, wie er war</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="228"/>
        <source>; held back %1 mm by the sheet</source>
        <translation>; vom Bogen um %1 mm zurückgehalten</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_report_text.cpp" line="243"/>
        <source>; %n patch(es) fold over onto themselves, where the surface overlaps itself: %1</source>
        <translation>
            <numerusform>; %n Flächenstück faltet sich auf sich selbst zurück, wo die Fläche sich selbst überlappt: %1</numerusform>
            <numerusform>; %n Flächenstücke falten sich auf sich selbst zurück, wo die Fläche sich selbst überlappt: %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_report_text.cpp" line="258"/>
        <source>; the development overlaps itself at %n patch(es) (%1) and cannot be cut from one sheet</source>
        <translation>
            <numerusform>; die Abwicklung überlappt sich selbst an %n Flächenstück (%1) und lässt sich nicht aus einem Bogen schneiden</numerusform>
            <numerusform>; die Abwicklung überlappt sich selbst an %n Flächenstücken (%1) und lässt sich nicht aus einem Bogen schneiden</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="264"/>
        <source>surface %1 %2</source>
        <translation>Fläche %1 %2</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="269"/>
        <source>patch %1: %2</source>
        <translation>Flächenstück %1: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="274"/>
        <source>nothing was solved.</source>
        <translation>es wurde nichts gelöst.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="264"/>
        <source>Solve</source>
        <translation>Lösen</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="282"/>
        <source>%1 discarded: the design changed meanwhile; it is unchanged.</source>
        <translation>%1 verworfen: der Entwurf hat sich inzwischen geändert; er ist unverändert.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="323"/>
        <source>Solve left the design as it was: solving made it less developable (largest developability residual %1 → %2).</source>
        <translation>Lösen hat den Entwurf unverändert gelassen: das Lösen machte ihn weniger abwickelbar (größtes Abwickelbarkeitsresiduum %1 → %2).</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="347"/>
        <location filename="../app/gui/solve_controller.cpp" line="392"/>
        <source>%1. %2</source>
        <comment>a verdict, then a sentence</comment>
        <translation>%1. %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_controller.cpp" line="351"/>
        <source>%n surface(s) left as they were: solving made them less developable.</source>
        <translation>
            <numerusform>%n Fläche unverändert gelassen: das Lösen machte sie weniger abwickelbar.</numerusform>
            <numerusform>%n Flächen unverändert gelassen: das Lösen machte sie weniger abwickelbar.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="363"/>
        <source>%1 discarded: the design changed while solving; nothing moved.</source>
        <translation>%1 verworfen: Der Entwurf hat sich während des Lösens geändert; nichts wurde bewegt.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="371"/>
        <source>%1 not applied: the motion %2; the design is unchanged.</source>
        <translation>%1 nicht angewendet, denn die Bewegung hätte so geendet: %2; der Entwurf bleibt unverändert.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_controller.cpp" line="387"/>
        <source>%1, kept developable: %n iteration(s), largest constraint residual %2.</source>
        <translation>
            <numerusform>%1, abwickelbar gehalten: %n Iteration, größtes Bedingungsresiduum %2.</numerusform>
            <numerusform>%1, abwickelbar gehalten: %n Iterationen, größtes Bedingungsresiduum %2.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="228"/>
        <location filename="../app/gui/solve_controller.cpp" line="315"/>
        <source>Solve failed: %1 The design is unchanged.</source>
        <translation>Lösen fehlgeschlagen: %1 Der Entwurf ist unverändert.</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="92"/>
        <source>Solve is not started while %1 runs; cancel it first (Esc).</source>
        <translation>Lösen wird nicht gestartet, solange %1 läuft; zuerst abbrechen (Esc).</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="84"/>
        <source>; vertex %1 lies on the straight line between the pinned vertices %2 and %3, which are as far apart as in the flat sheet, so bending cannot move it: the sheet stretched</source>
        <translation>; Ecke %1 liegt auf der Geraden zwischen den festgehaltenen Ecken %2 und %3, die so weit voneinander entfernt sind wie im flachen Blatt; Biegen kann sie daher nicht bewegen: das Blatt wurde gedehnt</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="91"/>
        <source>; vertex %1 lies inside the triangle of the pinned vertices %2, %3 and %4, which are as far apart as in the flat sheet, so bending cannot move it: the sheet stretched</source>
        <translation>; Ecke %1 liegt im Dreieck der festgehaltenen Ecken %2, %3 und %4, die so weit voneinander entfernt sind wie im flachen Blatt; Biegen kann sie daher nicht bewegen: das Blatt wurde gedehnt</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="183"/>
        <source>stopped at the last valid state, before a ruling, curve or patch collapsed</source>
        <translation>beim letzten gültigen Zustand angehalten, bevor eine Erzeugende, eine Kurve oder ein Flächenstück kollabierte</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="191"/>
        <source> (ended on iteration %1, the one with the smallest residual)</source>
        <translation> (endete bei Iteration %1, der mit dem kleinsten Residuum)</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="224"/>
        <source>taken back to where the drag started, since the drag %1: the design stays at its last developable state</source>
        <translation>zurückgenommen auf den Stand beim Drücken, denn das Ziehen hätte so geendet: %1; der Entwurf bleibt in seinem letzten abwickelbaren Zustand</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="292"/>
        <source>Solve result discarded: the design changed while solving.</source>
        <translation>Ergebnis verworfen: Der Entwurf hat sich während des Lösens geändert.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_controller.cpp" line="344"/>
        <source>Solved: %n iteration(s), largest constraint residual %1.</source>
        <translation>
            <numerusform>Gelöst: %n Iteration, größtes Residuum der Bedingungen %1.</numerusform>
            <numerusform>Gelöst: %n Iterationen, größtes Residuum der Bedingungen %1.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::SolverPanel</name>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="22"/>
        <source>Select Patches to Check</source>
        <translation>Zu prüfende Flächenstücke auswählen</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="75"/>
        <source>No solve yet. Tools ▸ Solve (Ctrl+Return) makes the design developable; the Drag tool keeps it developable while you pull vertices.</source>
        <translation>Noch nicht gelöst. Werkzeuge ▸ Lösen (Ctrl+Return) macht den Entwurf abwickelbar; das Ziehwerkzeug hält ihn abwickelbar, während Sie Ecken ziehen.</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="36"/>
        <source>Surf.</source>
        <translation>Fl.</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="36"/>
        <source>Iter.</source>
        <translation>It.</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="36"/>
        <source>Residual</source>
        <translation>Residuum</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="36"/>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="37"/>
        <source>Surface</source>
        <translation>Fläche</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="37"/>
        <source>Iteration</source>
        <translation>Iteration</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="38"/>
        <source>Largest constraint residual after the iteration</source>
        <translation>Größtes Residuum der Bedingungen nach der Iteration</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="39"/>
        <source>Time of the iteration in milliseconds</source>
        <translation>Dauer der Iteration in Millisekunden</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="50"/>
        <source>Selects the patches the last solve names: the least developable ones and those that fold over onto themselves</source>
        <translation>Wählt die Flächenstücke aus, die das letzte Lösen nennt: die am wenigsten abwickelbaren und die, die sich auf sich selbst zurückfalten</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="111"/>
        <source>No solve of the design as it is now: it was edited, or a step undone or redone, since the last report. Tools ▸ Solve (Ctrl+Return) reports on it.</source>
        <translation>Kein Lösen des Entwurfs in seinem jetzigen Zustand: Er wurde seit dem letzten Bericht bearbeitet, oder ein Schritt wurde rückgängig gemacht oder wiederhergestellt. Werkzeuge ▸ Lösen (Ctrl+Return) berichtet über ihn.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/panels/solver_panel.cpp" line="152"/>
        <source>&lt;b&gt;%1&lt;/b&gt;: %2&lt;br&gt;%n iteration(s) in %3 ms.</source>
        <translation>
            <numerusform>&lt;b&gt;%1&lt;/b&gt;: %2&lt;br&gt;%n Iteration in %3 ms.</numerusform>
            <numerusform>&lt;b&gt;%1&lt;/b&gt;: %2&lt;br&gt;%n Iterationen in %3 ms.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="176"/>
        <source>&lt;br&gt;Crease conditions, sampled along the creases: largest residual %1.</source>
        <translation>&lt;br&gt;Falzbedingungen, entlang der Falze abgetastet: größtes Residuum %1.</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="183"/>
        <source>&lt;br&gt;Least developable patches (normalised residual): %1</source>
        <translation>&lt;br&gt;Am wenigsten abwickelbare Flächenstücke (normiertes Residuum): %1</translation>
    </message>
</context>
<context>
    <name>devsurf::app::SplitAtRulingReaction</name>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="221"/>
        <source>The curves of this strip have a single spline interval, so a ruling can only be added after refining them (the shape stays the same). Refine now?</source>
        <translation>Die Kurven dieses Streifens haben nur ein Spline-Intervall; eine Erzeugende kann erst nach dem Verfeinern eingefügt werden (die Form bleibt gleich). Jetzt verfeinern?</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="226"/>
        <source>Cannot refine</source>
        <translation>Verfeinern nicht möglich</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="220"/>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="237"/>
        <source>Add Ruling</source>
        <translation>Erzeugende einfügen</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="201"/>
        <source>Add a ruling across the selected strip and the strips that share its curves. Select one strip or cone patch first.</source>
        <translation>Fügt eine Erzeugende quer über den ausgewählten Streifen und die Streifen mit denselben Kurven ein. Wählen Sie zuerst ein Streifen- oder Kegel-Flächenstück aus.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="238"/>
        <source>Where the new ruling crosses patch %1 and the strips that share its curves (green in the 3D view): per cent of the way along the strip. Rulings can go through the %n breakpoint(s) of the curves; refine the curves (Ctrl+Shift+R) for more.</source>
        <translation>
            <numerusform>Wo die neue Erzeugende Flächenstück %1 und die Streifen mit denselben Kurven kreuzt (grün in der 3D-Ansicht): Prozent des Wegs entlang des Streifens. Erzeugende können durch den %n Knoten der Kurven gehen; verfeinern Sie die Kurven (Strg+Umschalt+R) für mehr.</numerusform>
            <numerusform>Wo die neue Erzeugende Flächenstück %1 und die Streifen mit denselben Kurven kreuzt (grün in der 3D-Ansicht): Prozent des Wegs entlang des Streifens. Erzeugende können durch die %n Knoten der Kurven gehen; verfeinern Sie die Kurven (Strg+Umschalt+R) für mehr.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="269"/>
        <source>Cannot add the ruling</source>
        <translation>Erzeugende kann nicht eingefügt werden</translation>
    </message>
</context>
<context>
    <name>devsurf::app::SubdivideStripReaction</name>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="146"/>
        <source>Add a crease across the selected strip and the row of strips it belongs to. Select one patch of type strip (SRSR) first.</source>
        <translation>Fügt einen Falz quer über den ausgewählten Streifen und seine Streifenreihe ein. Wählen Sie zuerst ein Flächenstück vom Typ Streifen (SRSR) aus.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="157"/>
        <source>Add Crease</source>
        <translation>Falz einfügen</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="158"/>
        <source>Where the new crease crosses patch %1 and the strips of its row (green in the 3D view): per cent of the way from one curve of the strip to the other.</source>
        <translation>Wo der neue Falz Flächenstück %1 und die Streifen seiner Reihe kreuzt (grün in der 3D-Ansicht): Prozent des Wegs von einer Kurve des Streifens zur anderen.</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="187"/>
        <source>Cannot add the crease</source>
        <translation>Falz kann nicht eingefügt werden</translation>
    </message>
</context>
<context>
    <name>devsurf::app::Workspace</name>
    <message numerus="yes">
        <location filename="../app/gui/workspace.cpp" line="86"/>
        <source>… and %n more problem(s).</source>
        <translation>
            <numerusform>… und %n weiteres Problem.</numerusform>
            <numerusform>… und %n weitere Probleme.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="106"/>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="109"/>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="110"/>
        <source>%1 has unsaved changes. Do you want to save them?</source>
        <translation>%1 hat ungespeicherte Änderungen. Möchten Sie sie speichern?</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="124"/>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="131"/>
        <location filename="../app/gui/workspace.cpp" line="134"/>
        <source>Cannot open file</source>
        <translation>Datei kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="148"/>
        <source>Save Project As</source>
        <translation>Projekt speichern unter</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="151"/>
        <source>untitled.devsurf</source>
        <translation>unbenannt.devsurf</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="153"/>
        <source>DevSurf projects (*.devsurf)</source>
        <translation>DevSurf-Projekte (*.devsurf)</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="167"/>
        <source>Cannot save file</source>
        <translation>Datei kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="174"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="183"/>
        <source>New design from the example “%1”, holding the sheet it starts as</source>
        <translation>Neuer Entwurf aus dem Beispiel „%1“, er hält den Bogen fest, aus dem er beginnt</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="186"/>
        <source>New design from the example “%1”</source>
        <translation>Neuer Entwurf aus dem Beispiel „%1“</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="188"/>
        <source>Cannot create the example</source>
        <translation>Das Beispiel kann nicht erzeugt werden</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="199"/>
        <source>Recovered unsaved work</source>
        <translation>Ungespeicherte Arbeit wiederhergestellt</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="202"/>
        <location filename="../app/gui/workspace.cpp" line="205"/>
        <source>Cannot recover</source>
        <translation>Wiederherstellen nicht möglich</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="218"/>
        <source>an untitled design</source>
        <translation>einem unbenannten Entwurf</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="220"/>
        <source>Recover unsaved work</source>
        <translation>Ungespeicherte Arbeit wiederherstellen</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="221"/>
        <source>DevSurf did not close properly last time. Recover the unsaved changes to %1 from %2?</source>
        <translation>DevSurf wurde zuletzt nicht ordnungsgemäß beendet. Die ungespeicherten Änderungen an %1 vom %2 wiederherstellen?</translation>
    </message>
</context>
<context>
    <name>devsurf::views::SceneView</name>
    <message>
        <location filename="../views/scene_view.cpp" line="54"/>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <location filename="../views/scene_view.cpp" line="56"/>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <location filename="../views/scene_view_document.cpp" line="124"/>
        <source>Surface %1 is not valid and is not shown.</source>
        <translation>Fläche %1 ist ungültig und wird nicht angezeigt.</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="31"/>
        <source>vertex %1, pinned</source>
        <translation>Ecke %1, festgehalten</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="32"/>
        <source>vertex %1</source>
        <translation>Ecke %1</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="41"/>
        <source>edge %1 (R)</source>
        <translation>Kante %1 (R)</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="43"/>
        <source>edge %1 (S, crease)</source>
        <translation>Kante %1 (S, Falz)</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="45"/>
        <source>edge %1 (S, boundary)</source>
        <translation>Kante %1 (S, Rand)</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="56"/>
        <source>strip (SRSR)</source>
        <translation>Streifen (SRSR)</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="59"/>
        <source>pointed strip (SRS)</source>
        <translation>spitzer Streifen (SRS)</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="62"/>
        <source>cone (SRR)</source>
        <translation>Kegel (SRR)</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="65"/>
        <source>planar patch</source>
        <translation>ebenes Flächenstück</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="68"/>
        <source>invalid patch</source>
        <translation>ungültiges Flächenstück</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="71"/>
        <source>patch %1 (%2)</source>
        <translation>Flächenstück %1 (%2)</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="76"/>
        <source>surface %1: %2</source>
        <translation>Fläche %1: %2</translation>
    </message>
    <message>
        <location filename="../views/scene_view_distances.cpp" line="99"/>
        <source>Distance to design
(mm)</source>
        <translation>Abstand zum Entwurf
(mm)</translation>
    </message>
    <message>
        <location filename="../views/scene_view_distances.cpp" line="100"/>
        <source>covered</source>
        <translation>abgedeckt</translation>
    </message>
    <message>
        <location filename="../views/scene_view_distances.cpp" line="102"/>
        <source>Measuring…</source>
        <translation>Wird gemessen…</translation>
    </message>
    <message>
        <location filename="../views/scene_view_distances.cpp" line="109"/>
        <source>Updating…</source>
        <translation>Wird aktualisiert…</translation>
    </message>
</context>
<context>
    <name>devsurf::views::ViewOverlay</name>
    <message>
        <location filename="../views/view_overlay.cpp" line="72"/>
        <source>CF</source>
        <comment>badge: curved fold</comment>
        <translation>GF</translation>
    </message>
    <message>
        <location filename="../views/view_overlay.cpp" line="74"/>
        <source>G</source>
        <comment>badge: geodesic</comment>
        <translation>G</translation>
    </message>
    <message>
        <location filename="../views/view_overlay.cpp" line="76"/>
        <source>SU</source>
        <comment>badge: straight when unfolded</comment>
        <translation>GA</translation>
    </message>
    <message>
        <location filename="../views/view_overlay.cpp" line="144"/>
        <source>Mountain fold</source>
        <translation>Bergfalte</translation>
    </message>
    <message>
        <location filename="../views/view_overlay.cpp" line="148"/>
        <source>Valley fold</source>
        <translation>Talfalte</translation>
    </message>
    <message>
        <location filename="../views/view_overlay.cpp" line="152"/>
        <source>Crease, not folded</source>
        <translation>Falz, nicht gefaltet</translation>
    </message>
    <message>
        <location filename="../views/view_overlay.cpp" line="162"/>
        <source>Smooth ruling</source>
        <translation>Glatte Erzeugende</translation>
    </message>
    <message>
        <location filename="../views/view_overlay.cpp" line="165"/>
        <source>Sharp ruling</source>
        <translation>Scharfe Erzeugende</translation>
    </message>
    <message>
        <location filename="../views/view_overlay.cpp" line="168"/>
        <source>Sheet</source>
        <translation>Bogen</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="33"/>
        <source>Design developable surfaces and curved-crease origami.</source>
        <translation>Entwurf abwickelbarer Flächen und Origami mit gekrümmten Falzen.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="37"/>
        <source>A project file to open.</source>
        <translation>Eine zu öffnende Projektdatei.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="40"/>
        <source>Start with a built-in example.</source>
        <translation>Mit einem eingebauten Beispiel beginnen.</translation>
    </message>
</context>
</TS>
