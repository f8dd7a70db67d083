<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ja_JP">
<context>
    <name></name>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="34"/>
        <source>%1 is not a file DevSurf reads shapes from; choose a mesh (OBJ, PLY, STL, OFF) or a point cloud (XYZ, PTS).</source>
        <translation>%1 は DevSurf が形状を読み込めるファイルではありません。メッシュ (OBJ、PLY、STL、OFF) か点群 (XYZ、PTS) を選んでください。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="38"/>
        <source>%1 cannot be read; check that it exists and that you may read it.</source>
        <translation>%1 を読めません。ファイルが存在し、読み取り権限があるか確認してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="40"/>
        <source>%1 is too large; DevSurf takes up to %2 points and %3 triangles.</source>
        <translation>%1 は大きすぎます。DevSurf が扱えるのは %2 点、%3 三角形までです。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="44"/>
        <source>%1 is damaged or not a valid file of its type; nothing was imported.</source>
        <translation>%1 は壊れているか、その形式の正しいファイルではありません。何も読み込まれませんでした。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="47"/>
        <source>%1 ends before its last point or triangle; copy or export it again.</source>
        <translation>%1 は最後の点または三角形の前で終わっています。もう一度コピーするか書き出してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="50"/>
        <source>%1 holds a coordinate that is not a finite number of sensible size; nothing was imported.</source>
        <translation>%1 に妥当な大きさの有限な数でない座標があります。何も読み込まれませんでした。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="54"/>
        <source>A face of %1 names a point the file does not have; nothing was imported.</source>
        <translation>%1 の面が、ファイルにない点を指しています。何も読み込まれませんでした。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="57"/>
        <source>%1 holds no points to import.</source>
        <translation>%1 には読み込む点がありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="61"/>
        <source>No reference shape could be imported from %1.</source>
        <translation>%1 から参照形状を読み込めませんでした。</translation>
    </message>
</context>
<context>
    <name>AddSurfacesCommand</name>
    <message>
        <location filename="../model/document/commands/add_surfaces_command.cpp" line="19"/>
        <source>There is no surface to add.</source>
        <translation>追加する曲面がありません。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/add_surfaces_command.cpp" line="24"/>
        <source>A surface to add is not valid.</source>
        <translation>追加する曲面が有効ではありません。</translation>
    </message>
</context>
<context>
    <name>ApplySurfaceCommand</name>
    <message>
        <location filename="../model/document/commands/apply_surface_command.cpp" line="20"/>
        <source>The new shape cannot be applied</source>
        <translation>新しい形状を適用できません</translation>
    </message>
</context>
<context>
    <name>BoundedPattern</name>
    <message>
        <location filename="../app/gui/bounded_pattern.cpp" line="25"/>
        <source>Surface %1 reaches %2 m from the origin: even at a tolerance of 10 mm its pattern would take minutes to build, so there is none. Move its far control points closer.</source>
        <translation>曲面 %1 は原点から %2 m 離れた所まで達しています。許容差 10 mm でも型紙の作成に数分かかるため、型紙は作成しません。遠くの制御点を近づけてください。</translation>
    </message>
    <message>
        <location filename="../app/gui/bounded_pattern.cpp" line="38"/>
        <source>Surface %1 reaches %2 m from the origin: its curves are sampled to %3 mm, since %4 mm would take minutes.</source>
        <translation>曲面 %1 は原点から %2 m 離れた所まで達しています。%4 mm では数分かかるため、曲線を %3 mm でサンプリングします。</translation>
    </message>
</context>
<context>
    <name>CreaseConditionCommand</name>
    <message>
        <location filename="../model/document/commands/crease_condition_command.cpp" line="8"/>
        <source>Curved fold</source>
        <translation>曲線折り</translation>
    </message>
    <message>
        <location filename="../model/document/commands/crease_condition_command.cpp" line="10"/>
        <source>Geodesic</source>
        <translation>測地線</translation>
    </message>
    <message>
        <location filename="../model/document/commands/crease_condition_command.cpp" line="12"/>
        <source>Straight when unfolded</source>
        <translation>展開時に直線</translation>
    </message>
    <message>
        <location filename="../model/document/commands/crease_condition_command.cpp" line="16"/>
        <source>No condition</source>
        <translation>条件なし</translation>
    </message>
    <message>
        <location filename="../model/document/commands/crease_condition_command.cpp" line="24"/>
        <source>Select at least one crease.</source>
        <translation>折り線を 1 本以上選択してください。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/crease_condition_command.cpp" line="34"/>
        <source>Edge %1 does not exist.</source>
        <translation>辺 %1 は存在しません。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/crease_condition_command.cpp" line="38"/>
        <source>Edge %1 is a ruling; conditions apply to creases (curves between two patches).</source>
        <translation>辺 %1 は母線です。条件は折り線 (2 つのパッチの間の曲線) に設定します。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/crease_condition_command.cpp" line="44"/>
        <source>Edge %1 is a curve on the boundary, not a crease; conditions apply to curves between two patches.</source>
        <translation>辺 %1 は境界の曲線で、折り線ではありません。条件は 2 つのパッチの間の曲線に設定します。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/crease_condition_command.cpp" line="51"/>
        <source>The selected creases already have the condition &quot;%1&quot;.</source>
        <translation>選択した折り線にはすでに条件「%1」が設定されています。</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/crease_condition_command.cpp" line="55"/>
        <source>Clear the condition of %n creases</source>
        <translation>
            <numerusform>%n 本の折り線の条件を解除</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/crease_condition_command.cpp" line="56"/>
        <source>%1 on %n creases</source>
        <translation>
            <numerusform>%n 本の折り線に%1</numerusform>
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
        <translation>サイズ × サイズ個のストリップからなる平らな長方形。</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="13"/>
        <source>A flat annulus of size rings cut by radial rulings.</source>
        <translation>放射状の母線で区切られた、サイズ個の環からなる平らな円環。</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="17"/>
        <source>A closed cylinder of strips, size sectors around.</source>
        <translation>周方向にサイズ個の区画を持つ、ストリップからなる閉じた円柱。</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="21"/>
        <source>A flat square of size × size strips with curved creases, ready to fold: every interior crease carries the curved-fold condition and the bottom corners are pinned. Drag the middle vertices up (Drag tool, G).</source>
        <translation>曲がった折り線をもつ サイズ × サイズ 個のストリップからなる平らな正方形で、すぐに折れます: 内部の折り線にはすべて曲線折りの条件があり、下の角は固定されています。中央の頂点を上へドラッグしてください (ドラッグツール、G)。</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="28"/>
        <source>Two strips joined by one curved crease with the curved-fold condition, the bottom corners pinned; size intervals per curve. Drag a top corner up to fold it.</source>
        <translation>曲線折りの条件をもつ 1 本の曲がった折り線でつながった 2 つのストリップ。下の角は固定、曲線ごとに サイズ 個の区間。上の角を上へドラッグすると折れます。</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="34"/>
        <source>A disk with one curved crease between two strips, folded from a disk-shaped sheet it keeps; the crease&apos;s middle and the rim below it pinned; size faces per strip. Drag the top of the rim up and in towards the crease to fold it.</source>
        <translation>2 枚の帯の間に曲線の折り線が 1 本ある円板で、保持している円板の形のシートから折られます。折り線の中点とその下の縁の点が固定されています。帯ごとに size 個の面。縁の一番上の点を上へ、折り線の方へドラッグすると折れます。</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="41"/>
        <source>A ring of size bands folded along concentric curved creases, mountain and valley in turn, exactly: every crease a fold in a horizontal plane, every band a piece of one cone. It keeps its development on its sheet, a ring whose edges wave with its eight lobes; three inner vertices pinned.</source>
        <translation>size 本の帯からなるリングを、同心の曲線の折り目に沿って山折りと谷折りを交互に、厳密に折ったもの: どの折り目も水平面内の折りで、どの帯も一つの錐面の一部です。展開図は、八つの膨らみに沿って縁が波打つリング状のシートの上に保持されます。内側の頂点 3 つを固定しています。</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="49"/>
        <source>A closed torus of size bands of cones, 2 × size strips around: developable strip by strip but not from one sheet; its cutting pattern has one piece per band.</source>
        <translation>錐面の帯 size 本からなる閉じたトーラスで、周方向に 2 × size 枚の帯があります。帯ごとには可展ですが 1 枚のシートからは作れません。型紙は帯ごとに 1 枚の部品になります。</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="55"/>
        <source>A pleated column after Huffman&apos;s hexagonal column: a tube folded along size upright creases with the curved-fold condition, three bottom vertices pinned. It keeps its development around the cylinder it unrolls from. Drag a top vertex up or in.</source>
        <translation>ハフマンの六角柱にならったプリーツ状の柱: 曲線折りの条件を持つ size 本の縦の折り目に沿って折った筒で、下端の頂点 3 つを固定しています。展開図は、巻き戻すと得られる円柱の周りに保持されます。上端の頂点を上または内側にドラッグしてください。</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="61"/>
        <source>A strip, a pointed strip, a cone and a planar patch; size intervals per curve.</source>
        <translation>ストリップ、尖ったストリップ、錐面、平面パッチ。曲線ごとにサイズ個の区間。</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="68"/>
        <source>A flat square of size × size strips with curved creases carrying the curved-fold condition, holding its square sheet with the creases where they lie in it, its bottom-left corner pinned. Select the four middle vertices and drag them up (Drag tool, G) to fold it.</source>
        <translation>曲線折りの条件を持つ曲線の折り線が入った size × size 本のストリップからなる平らな正方形。正方形のシートを保持し、折り線はシート上の今の位置に保たれ、左下の角が固定されています。中央の4頂点を選択して上にドラッグすると (ドラッグツール、G) 折れます。</translation>
    </message>
    <message>
        <location filename="../app/text/example_text.cpp" line="76"/>
        <source>Two strips joined by one curved crease with the curved-fold condition, holding its rectangular sheet with the crease where it lies in it, its bottom-left corner pinned; size intervals per curve. Select both top corners and drag them up and in towards the crease to fold it.</source>
        <translation>曲線折りの条件を持つ1本の曲線の折り線でつながった2本のストリップ。長方形のシートを保持し、折り線はシート上の今の位置に保たれ、左下の角が固定されています。曲線1本あたり size 区間。上の両角を選択して、上へ、そして折り線の方へドラッグすると折れます。</translation>
    </message>
</context>
<context>
    <name>FaceType</name>
    <message>
        <location filename="../app/text/face_type_text.cpp" line="10"/>
        <source>strip (SRSR)</source>
        <translation>ストリップ (SRSR)</translation>
    </message>
    <message>
        <location filename="../app/text/face_type_text.cpp" line="12"/>
        <source>pointed strip (SRS)</source>
        <translation>尖ったストリップ (SRS)</translation>
    </message>
    <message>
        <location filename="../app/text/face_type_text.cpp" line="14"/>
        <source>cone (SRR)</source>
        <translation>錐面 (SRR)</translation>
    </message>
    <message>
        <location filename="../app/text/face_type_text.cpp" line="16"/>
        <source>planar patch</source>
        <translation>平面パッチ</translation>
    </message>
    <message>
        <location filename="../app/text/face_type_text.cpp" line="20"/>
        <source>invalid labelling</source>
        <translation>無効なラベル付け</translation>
    </message>
</context>
<context>
    <name>JoinSurfacesCommand</name>
    <message>
        <location filename="../model/document/commands/join_surfaces_command.cpp" line="27"/>
        <source>Choose at least two surfaces of the design to join.</source>
        <translation>結合するデザインのサーフェスを 2 つ以上選んでください。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/join_surfaces_command.cpp" line="31"/>
        <source>The joined surface is not valid.</source>
        <translation>結合したサーフェスが有効ではありません。</translation>
    </message>
</context>
<context>
    <name>LanguageMenu</name>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="30"/>
        <source>Language</source>
        <translation>言語</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="31"/>
        <source>The interface will use this language from the next start of DevSurf.</source>
        <translation>次回 DevSurf を起動したときから、この言語で表示します。</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="37"/>
        <source>&amp;Restart Now</source>
        <translation>今すぐ再起動(&amp;R)</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="40"/>
        <source>Save your changes and restart DevSurf to use it now.</source>
        <translation>今すぐ使うには、変更を保存して DevSurf を再起動してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="42"/>
        <source>&amp;Later</source>
        <translation>後で(&amp;L)</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="42"/>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="60"/>
        <source>&amp;Language</source>
        <translation>言語(&amp;L)</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="68"/>
        <source>&amp;System Language</source>
        <translation>システムの言語(&amp;S)</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="69"/>
        <source>&amp;English</source>
        <translation>英語 (English)(&amp;E)</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="70"/>
        <source>&amp;German (Deutsch)</source>
        <translation>ドイツ語 (Deutsch)(&amp;G)</translation>
    </message>
    <message>
        <location filename="../app/gui/language_menu.cpp" line="71"/>
        <source>&amp;Japanese (日本語)</source>
        <translation>日本語(&amp;J)</translation>
    </message>
</context>
<context>
    <name>MergeStripsCommand</name>
    <message>
        <location filename="../model/document/commands/merge_strips_command.cpp" line="9"/>
        <source>Remove ruling %1</source>
        <translation>母線 %1 を削除</translation>
    </message>
    <message>
        <location filename="../model/document/commands/merge_strips_command.cpp" line="11"/>
        <source>Ruling %1 cannot be removed</source>
        <translation>母線 %1 は削除できません</translation>
    </message>
</context>
<context>
    <name>MoveVerticesCommand</name>
    <message>
        <location filename="../model/document/commands/move_vertices_command.cpp" line="20"/>
        <source>The vertices cannot be moved by an offset that is not a finite number.</source>
        <translation>有限の数でない移動量では頂点を移動できません。</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/move_vertices_command.cpp" line="23"/>
        <source>Move %n vertices</source>
        <translation>
            <numerusform>%n 個の頂点を移動</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/document/commands/move_vertices_command.cpp" line="36"/>
        <source>The vertices cannot be rotated</source>
        <translation>頂点を回転できません</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/move_vertices_command.cpp" line="38"/>
        <source>Rotate %n vertices</source>
        <translation>
            <numerusform>%n 個の頂点を回転</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/document/commands/move_vertices_command.cpp" line="46"/>
        <source>The vertices cannot be moved</source>
        <translation>頂点を移動できません</translation>
    </message>
</context>
<context>
    <name>OutputProblem</name>
    <message>
        <location filename="../app/gui/output_problem_text.cpp" line="16"/>
        <source>“%1” is the project file of this design: exporting over it would destroy the design. Choose another file name.</source>
        <translation>「%1」はこのデザインのプロジェクトファイルです。上書きしてエクスポートするとデザインが失われます。別のファイル名を選んでください。</translation>
    </message>
    <message>
        <location filename="../app/gui/output_problem_text.cpp" line="21"/>
        <source>“%1” is a folder. Choose a file name.</source>
        <translation>「%1」はフォルダーです。ファイル名を選んでください。</translation>
    </message>
    <message>
        <location filename="../app/gui/output_problem_text.cpp" line="24"/>
        <source>“%1” is a device, pipe or socket, not a file. Choose a file name.</source>
        <translation>「%1」はデバイス、パイプまたはソケットで、ファイルではありません。ファイル名を選んでください。</translation>
    </message>
    <message>
        <location filename="../app/gui/output_problem_text.cpp" line="43"/>
        <source>There is not enough memory to open “%1”.</source>
        <translation>「%1」を開くためのメモリが足りません。</translation>
    </message>
</context>
<context>
    <name>PinVerticesCommand</name>
    <message>
        <location filename="../model/document/commands/pin_vertices_command.cpp" line="9"/>
        <source>Select at least one vertex to pin.</source>
        <translation>固定する頂点を少なくとも 1 つ選択してください。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/pin_vertices_command.cpp" line="10"/>
        <source>Select at least one vertex to unpin.</source>
        <translation>固定を解除する頂点を少なくとも 1 つ選択してください。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/pin_vertices_command.cpp" line="20"/>
        <source>Vertex %1 does not exist.</source>
        <translation>頂点 %1 は存在しません。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/pin_vertices_command.cpp" line="25"/>
        <source>The selected vertices are already pinned.</source>
        <translation>選択した頂点はすでに固定されています。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/pin_vertices_command.cpp" line="26"/>
        <source>The selected vertices are not pinned.</source>
        <translation>選択した頂点は固定されていません。</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/pin_vertices_command.cpp" line="29"/>
        <source>Pin %n vertices</source>
        <translation>
            <numerusform>%n 個の頂点を固定</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/pin_vertices_command.cpp" line="29"/>
        <source>Unpin %n vertices</source>
        <translation>
            <numerusform>%n 個の頂点の固定を解除</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ProblemText</name>
    <message>
        <location filename="../app/text/problem_text.cpp" line="39"/>
        <source>no patch</source>
        <translation>パッチなし</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="42"/>
        <source>patch %1</source>
        <translation>パッチ %1</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="44"/>
        <source>patches %1</source>
        <translation>パッチ %1</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="49"/>
        <source>degree %1, C%2, 1 interval</source>
        <translation>次数 %1、C%2、区間数 1</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="51"/>
        <source>degree %1, C%2, %3 intervals</source>
        <translation>次数 %1、C%2、区間数 %3</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="59"/>
        <source>Surface %1</source>
        <translation>曲面 %1</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="61"/>
        <source>Surface %1 “%2”</source>
        <translation>曲面 %1「%2」</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="68"/>
        <source>The surface has no patches.</source>
        <translation>曲面にパッチがありません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="70"/>
        <source>Vertex id %1 is used twice.</source>
        <translation>頂点 ID %1 が二重に使われています。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="71"/>
        <source>Edge id %1 is used twice.</source>
        <translation>辺 ID %1 が二重に使われています。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="72"/>
        <source>Patch id %1 is used twice.</source>
        <translation>パッチ ID %1 が二重に使われています。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="74"/>
        <source>Vertex %1 does not exist.</source>
        <translation>頂点 %1 は存在しません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="75"/>
        <source>Edge %1 does not exist.</source>
        <translation>辺 %1 は存在しません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="76"/>
        <source>Patch %1 does not exist.</source>
        <translation>パッチ %1 は存在しません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="78"/>
        <source>Edge %1 does not join two distinct existing vertices.</source>
        <translation>辺 %1 は異なる 2 つの既存の頂点を結んでいません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="80"/>
        <source>Edge %1 duplicates the edge between vertices %2 and %3.</source>
        <translation>辺 %1 は頂点 %2 と %3 の間の辺と重複しています。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="85"/>
        <source>Patch %1 has fewer than three corners.</source>
        <translation>パッチ %1 の角が 3 つ未満です。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="87"/>
        <source>Patch %1 visits a vertex twice.</source>
        <translation>パッチ %1 は同じ頂点を 2 回通ります。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="89"/>
        <source>Patch %1 refers to vertex %2, which does not exist.</source>
        <translation>パッチ %1 は存在しない頂点 %2 を参照しています。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="91"/>
        <source>Patch %1 runs along the edge from vertex %2 to vertex %3 in the same direction as another patch: patches must be oriented consistently and an edge can border at most two patches.</source>
        <translation>パッチ %1 は頂点 %2 から頂点 %3 への辺を別のパッチと同じ向きにたどっています。パッチの向きはそろっている必要があり、1 本の辺に接するパッチは 2 つまでです。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="98"/>
        <source>Patch %1 cannot be attached without making the surface non-manifold.</source>
        <translation>パッチ %1 を追加すると曲面が非多様体になるため追加できません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="101"/>
        <source>There is no edge between vertices %1 and %2.</source>
        <translation>頂点 %1 と %2 の間に辺がありません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="103"/>
        <source>Edge %1 is a curve; only rulings are smooth or sharp.</source>
        <translation>辺 %1 は曲線です。滑らか・鋭いの区別があるのは母線だけです。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="105"/>
        <source>Vertex %1 belongs to no patch.</source>
        <translation>頂点 %1 はどのパッチにも属していません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="106"/>
        <source>Edge %1 belongs to no patch.</source>
        <translation>辺 %1 はどのパッチにも属していません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="108"/>
        <source>Vertex %1 lies beyond the id counter.</source>
        <translation>頂点 %1 は ID カウンタを超えています。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="109"/>
        <source>Edge %1 lies beyond the id counter.</source>
        <translation>辺 %1 は ID カウンタを超えています。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="110"/>
        <source>Patch %1 lies beyond the id counter.</source>
        <translation>パッチ %1 は ID カウンタを超えています。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="112"/>
        <source>Edge %1 is a ruling but carries spline data.</source>
        <translation>辺 %1 は母線ですがスプラインのデータを持っています。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="114"/>
        <source>Edge %1 is marked smooth but is not shared by two patches.</source>
        <translation>辺 %1 は滑らかと指定されていますが、2 つのパッチに共有されていません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="116"/>
        <source>Edge %1 is a curve but is marked smooth (only rulings are).</source>
        <translation>辺 %1 は曲線ですが滑らかと指定されています（指定できるのは母線だけです）。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="118"/>
        <source>Edge %1 has an invalid spline space (%2).</source>
        <translation>辺 %1 のスプライン空間 (%2) は無効です。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="122"/>
        <source>Edge %1 has %2 control points; its spline space (%3) needs %4.</source>
        <translation>辺 %1 の制御点は %2 個ですが、そのスプライン空間 (%3) には %4 個必要です。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="128"/>
        <source>Edge %1 has a control point that is not a finite number.</source>
        <translation>辺 %1 に有限の数でない制御点があります。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="131"/>
        <source>Edge %1 does not start at its vertex %2.</source>
        <translation>辺 %1 が頂点 %2 から始まっていません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="132"/>
        <source>Edge %1 does not end at its vertex %2.</source>
        <translation>辺 %1 が頂点 %2 で終わっていません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="134"/>
        <source>Edge %1 carries a crease condition but is not shared by two patches.</source>
        <translation>辺 %1 には折り線の条件がありますが、2 つのパッチに共有されていません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="137"/>
        <source>Patch %1 is labelled %2; a patch must be an SRSR strip, an SRS strip, an SRR cone or a polygon of rulings only (R…R).</source>
        <translation>パッチ %1 のラベルは %2 です。パッチは SRSR ストリップ、SRS ストリップ、SRR 錐面、または母線だけの多角形 (R…R) でなければなりません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="142"/>
        <source>Curves %1 and %2 are connected through patches but use different spline spaces (%3 and %4).</source>
        <translation>曲線 %1 と %2 はパッチを介してつながっていますが、スプライン空間が異なります (%3 と %4)。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="148"/>
        <source>The kept development has %1 points, but the surface&apos;s sampled mesh has %2.</source>
        <translation>保持された展開図の点は %1 個ですが、曲面のサンプリングメッシュは %2 個です。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="152"/>
        <source>A point of the kept development is not a finite number.</source>
        <translation>保持された展開図の点に有限でない数があります。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="155"/>
        <source>The sheet&apos;s inner radius must be smaller than its outer radius.</source>
        <translation>シートの内径は外径より小さくなければなりません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="158"/>
        <source>The sheet&apos;s outline has no closed loop enclosing an area.</source>
        <translation>シートの輪郭に面積を囲む閉じたループがありません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="161"/>
        <source>A crease curve of the sheet has too few points, a point that is not a finite number, or is not there.</source>
        <translation>シートの折り線カーブの点が少なすぎるか、有限でない点があるか、存在しません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="164"/>
        <source>The sheet&apos;s sizes must be finite and greater than zero.</source>
        <translation>シートの寸法は有限で 0 より大きくなければなりません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="166"/>
        <source>Vertex %1 (of %2) has a position that is not a finite number.</source>
        <translation>頂点 %1（%2）の位置が有限の数ではありません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="170"/>
        <source>Vertex %1 (of %2) lies %3 mm from the origin; coordinates beyond %4 mm (1 km) are not accepted.</source>
        <translation>頂点 %1（%2）は原点から %3 mm 離れています。%4 mm (1 km) を超える座標は受け付けません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="175"/>
        <source>Edge %1 (a curve of %2) has a control point beyond %3 mm from the origin.</source>
        <translation>辺 %1（%2 の曲線）に原点から %3 mm より遠い制御点があります。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="179"/>
        <source>Edge %1 (a curve of %2) has zero length.</source>
        <translation>辺 %1（%2 の曲線）の長さがゼロです。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="181"/>
        <source>Edge %1 (a curve of %2) is pinched: a stretch of it has shrunk to a point.</source>
        <translation>辺 %1（%2 の曲線）がくびれています。その一部が 1 点に縮んでいます。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="185"/>
        <source>Edge %1 (a ruling of %2) has zero length.</source>
        <translation>辺 %1（%2 の母線）の長さがゼロです。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="187"/>
        <source>Patch %1 has coincident vertices %2 and %3.</source>
        <translation>パッチ %1 の頂点 %2 と %3 が一致しています。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="192"/>
        <source>Patch %1 has zero area.</source>
        <translation>パッチ %1 の面積がゼロです。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="194"/>
        <source>Patch %1 is a %2; only an SRSR strip can be cut by a new crease.</source>
        <translation>パッチ %1 は%2です。新しい折り線で分割できるのは SRSR ストリップだけです。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="198"/>
        <source>The new crease cannot continue across ruling edge %1 into patch %2, a %3; a row of strips can only be cut where its rulings border SRSR strips, planar patches or the boundary.</source>
        <translation>新しい折り線は母線の辺 %1 を越えてパッチ %2（%3）へ続けられません。ストリップの列を分割できるのは、その母線が SRSR ストリップ、平面パッチまたは境界に接する場所だけです。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="205"/>
        <source>The row of strips through patch %1 closes on itself with its sides swapped, so it cannot be cut at one distance between its curves.</source>
        <translation>パッチ %1 を通るストリップの列は左右が入れ替わって閉じているため、曲線間の一定の位置で分割できません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="209"/>
        <source>The new crease must lie strictly between the strip&apos;s two curves (0 &lt; t &lt; 1, not %1).</source>
        <translation>新しい折り線はストリップの 2 本の曲線の間になければなりません（0 &lt; t &lt; 1、%1 ではなく）。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="213"/>
        <source>No edge was given to relabel.</source>
        <translation>ラベルを変更する辺が指定されていません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="215"/>
        <source>Edge %1 is not a spline curve.</source>
        <translation>辺 %1 はスプライン曲線ではありません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="217"/>
        <source>Patch %1 is a %2; a ruling can only be added to a strip or a cone.</source>
        <translation>パッチ %1 は%2です。母線を追加できるのはストリップか錐面だけです。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="221"/>
        <source>The curves of patch %1 have a single interval; refine them before adding a ruling.</source>
        <translation>パッチ %1 の曲線は区間が 1 つだけです。母線を追加する前に細分してください。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="225"/>
        <source>A ruling can only be added at an interior breakpoint i/%1 of the curves of patch %2 (1 ≤ i ≤ %3, not %4); refine the curves for finer positions.</source>
        <translation>母線を追加できるのはパッチ %2 の曲線の内部の区切り点 i/%1 だけです（1 ≤ i ≤ %3、%4 ではなく）。細かい位置には曲線を細分してください。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="232"/>
        <source>The curves connected to patch %1 meet themselves reversed, so no ruling position is consistent across them.</source>
        <translation>パッチ %1 につながる曲線は逆向きに自分自身と出会うため、すべてに合う母線の位置がありません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="236"/>
        <source>Curve %1 uses a different spline space from the curves of patch %2.</source>
        <translation>曲線 %1 のスプライン空間はパッチ %2 の曲線と異なります。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="240"/>
        <source>Refining needs a factor of at least 2, not %1.</source>
        <translation>細分には 2 以上の倍率が必要です（%1 ではなく）。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="242"/>
        <source>The curves of edge %1 already have %2 intervals; refining them beyond %3 is not supported.</source>
        <translation>辺 %1 の曲線はすでに区間数 %2 です。%3 を超える細分には対応していません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="248"/>
        <source>No vertex was given to move.</source>
        <translation>移動する頂点が指定されていません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="250"/>
        <source>A rotation needs a finite axis point, a non-zero axis direction and a finite angle.</source>
        <translation>回転には有限の軸上の点、ゼロでない軸方向、有限の角度が必要です。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="257"/>
        <source>There is no example called “%1”; the examples are %2.</source>
        <translation>「%1」という例はありません。例は %2 です。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="261"/>
        <source>The size of the example “%1” must be between %2 and %3, not %4.</source>
        <translation>例「%1」のサイズは %2 から %3 の間でなければなりません（%4 ではなく）。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="267"/>
        <source>The number of samples per spline interval must be between 1 and %1, not %2.</source>
        <translation>スプライン区間あたりのサンプル数は 1 から %1 の間でなければなりません（%2 ではなく）。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="271"/>
        <source>Patch %1 is not a strip or a cone.</source>
        <translation>パッチ %1 はストリップでも錐面でもありません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="273"/>
        <source>The two shapes do not have the same patches.</source>
        <translation>2 つの形状のパッチが一致しません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="275"/>
        <source>Edge %1 has a crease condition but is a boundary curve, not a crease.</source>
        <translation>辺 %1 には折り線の条件がありますが、折り線ではなく境界曲線です。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="278"/>
        <source>Edge %1 has a crease condition but a cone or planar patch lies beside it; crease conditions need a strip on either side.</source>
        <translation>辺 %1 には折り線の条件がありますが、隣に錐面または平面パッチがあります。折り線の条件には両側にストリップが必要です。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="283"/>
        <source>Edge %1 has a crease condition but its curve is of degree %2; a crease condition needs degree 2 or more.</source>
        <translation>辺 %1 には折り線の条件がありますが、曲線の次数が %2 です。折り線の条件には次数 2 以上が必要です。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/text/problem_text.cpp" line="289"/>
        <source>The surface is not one sheet: it has %n separate part(s).</source>
        <translation>
            <numerusform>曲面は 1 枚のシートではありません: %n 個の部分に分かれています。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="292"/>
        <source>The surface is not one flat sheet: its unfolding misses closing up by %1 mm.</source>
        <translation>曲面は 1 枚の平らなシートではありません: 展開図が %1 mm 閉じません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="295"/>
        <source>Edge %1 cannot be welded: a weld joins two boundary edges of the same kind (two curves or two rulings) of two different patches.</source>
        <translation>辺 %1 は溶接できません。溶接できるのは、異なる二つのパッチの同じ種類（二本の曲線または二本の母線）の境界辺どうしです。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="299"/>
        <source>Edges %1 and %2 lie up to %3 mm apart, more than the %4 mm within which they can be welded.</source>
        <translation>辺 %1 と %2 は最大 %3 mm 離れており、溶接できる %4 mm を超えています。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="305"/>
        <source>The strips beside edge %1 cannot be merged: it must be a ruling between two strips whose curves are boundary curves of the same degree and smoothness, and its ends may belong to no other patch.</source>
        <translation>辺 %1 の両側のストリップは結合できません。辺は、曲線が同じ次数と滑らかさの境界曲線である二つのストリップの間の母線でなければならず、その端点は他のパッチに属してはいけません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="312"/>
        <source>DevSurf met an internal error (%1). Please report it.</source>
        <translation>DevSurf で内部エラーが発生しました (%1)。報告してください。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="330"/>
        <source>The sheet size must be positive; the pieces are laid out side by side.</source>
        <translation>シートの大きさは正でなければなりません。ピースは横に並べて配置します。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="332"/>
        <source>%1 is not valid and has no pattern: %2</source>
        <translation>%1 は無効で型紙がありません: %2</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="335"/>
        <source>%1 could not be developed: %2</source>
        <translation>%1 を展開できませんでした: %2</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="338"/>
        <source>Piece %1 (%2) overlaps itself at patches %3 and cannot be cut from one sheet.</source>
        <translation>ピース %1（%2）はパッチ %3 で自分自身と重なっており、1 枚のシートから切り出せません。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="341"/>
        <source>Pieces %1 (patches %2) and %3 (patches %4) overlap on sheet %5.</source>
        <translation>ピース %1（パッチ %2）と %3（パッチ %4）がシート %5 上で重なっています。</translation>
    </message>
    <message>
        <location filename="../app/text/problem_text.cpp" line="346"/>
        <source>Piece %1 (%2) measures %3 × %4 mm and does not fit on the %5 × %6 mm sheet with a %7 mm gap.</source>
        <translation>ピース %1（%2）は %3 × %4 mm で、%7 mm の間隔をとると %5 × %6 mm のシートに収まりません。</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="35"/>
        <source>Laser bed 600 × 400 mm</source>
        <translation>レーザー加工機のベッド 600 × 400 mm</translation>
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
        <translation>レター (8.5 × 11 in)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="39"/>
        <source>Custom</source>
        <translation>カスタム</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="36"/>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="44"/>
        <source>Nothing to print</source>
        <translation>印刷するものがありません</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="46"/>
        <source>The design has no surface to develop.</source>
        <translation>デザインに展開できる曲面がありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="62"/>
        <source>Printing the cutting pattern…</source>
        <translation>型紙を印刷しています…</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="62"/>
        <source>Cancel</source>
        <translation>キャンセル</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="152"/>
        <source>Export &amp;Cutting Pattern…</source>
        <translation>型紙をエクスポート(&amp;C)…</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="154"/>
        <source>&amp;Print…</source>
        <translation>印刷(&amp;P)…</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="157"/>
        <source>Print Pre&amp;view…</source>
        <translation>印刷プレビュー(&amp;V)…</translation>
    </message>
</context>
<context>
    <name>ReferenceCurvesCommand</name>
    <message>
        <location filename="../model/document/commands/reference_curves_command.cpp" line="31"/>
        <source>There are no curves to import.</source>
        <translation>読み込む曲線がありません。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/reference_curves_command.cpp" line="35"/>
        <source>A curve to import has fewer than two points or a coordinate that is not a number.</source>
        <translation>読み込む曲線に、点が 2 つ未満のもの、または数値でない座標を持つものがあります。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/reference_curves_command.cpp" line="44"/>
        <source>Import Curves</source>
        <translation>曲線を読み込む</translation>
    </message>
    <message>
        <location filename="../model/document/commands/reference_curves_command.cpp" line="51"/>
        <source>Select at least one reference curve to remove.</source>
        <translation>削除する参照曲線を 1 本以上選択してください。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/reference_curves_command.cpp" line="55"/>
        <source>Reference curve %1 does not exist.</source>
        <translation>参照曲線 %1 は存在しません。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/reference_curves_command.cpp" line="65"/>
        <source>Remove Reference Curves</source>
        <translation>参照曲線を削除</translation>
    </message>
    <message>
        <location filename="../model/document/commands/reference_curves_command.cpp" line="71"/>
        <source>The design has no reference curves.</source>
        <translation>デザインに参照曲線はありません。</translation>
    </message>
</context>
<context>
    <name>ReferenceShapesCommand</name>
    <message>
        <location filename="../model/document/commands/reference_shapes_command.cpp" line="39"/>
        <source>The shape to import has no points, a coordinate that is not a number or a triangle naming a point it does not have.</source>
        <translation>読み込む形状に点がないか、数値でない座標があるか、存在しない点を指す三角形があります。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/reference_shapes_command.cpp" line="45"/>
        <source>Import Reference Shape</source>
        <translation>参照形状を読み込む</translation>
    </message>
    <message>
        <location filename="../model/document/commands/reference_shapes_command.cpp" line="50"/>
        <source>The design has no reference shapes.</source>
        <translation>デザインに参照形状がありません。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/reference_shapes_command.cpp" line="53"/>
        <source>Remove Reference Shapes</source>
        <translation>参照形状を削除</translation>
    </message>
</context>
<context>
    <name>RefineSplineClassCommand</name>
    <message>
        <location filename="../model/document/commands/refine_spline_class_command.cpp" line="9"/>
        <source>Refine curves</source>
        <translation>曲線を細分化</translation>
    </message>
    <message>
        <location filename="../model/document/commands/refine_spline_class_command.cpp" line="11"/>
        <source>The curves of edge %1 cannot be refined</source>
        <translation>辺 %1 の曲線を細分化できません</translation>
    </message>
</context>
<context>
    <name>RelabelEdgeCommand</name>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="16"/>
        <source>Select at least one edge to relabel.</source>
        <translation>ラベルを変更する辺を少なくとも 1 本選択してください。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="23"/>
        <source>Make edge %1 a spline curve</source>
        <translation>辺 %1 をスプライン曲線にする</translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="24"/>
        <source>Make edge %1 a ruling</source>
        <translation>辺 %1 を母線にする</translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="25"/>
        <source>Edge %1 cannot become a spline curve</source>
        <translation>辺 %1 はスプライン曲線にできません</translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="26"/>
        <source>Edge %1 cannot become a ruling</source>
        <translation>辺 %1 は母線にできません</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="28"/>
        <source>Relabel %n edges</source>
        <translation>
            <numerusform>%n 本の辺のラベルを変更</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="29"/>
        <source>The edges cannot be relabelled</source>
        <translation>辺のラベルを変更できません</translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="39"/>
        <source>Edge %1 is already a spline curve.</source>
        <translation>辺 %1 はすでにスプライン曲線です。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/relabel_edge_command.cpp" line="40"/>
        <source>Edge %1 is already a ruling.</source>
        <translation>辺 %1 はすでに母線です。</translation>
    </message>
</context>
<context>
    <name>SceneView</name>
    <message>
        <location filename="../views/quality_colours.cpp" line="81"/>
        <source>developable</source>
        <translation>可展</translation>
    </message>
    <message>
        <location filename="../views/quality_colours.cpp" line="98"/>
        <source>Developability
|det(a-b, a&apos;, b&apos;)|
(ratio)</source>
        <translation>可展性
|det(a-b, a&apos;, b&apos;)|
(比)</translation>
    </message>
    <message>
        <location filename="../views/quality_colours.cpp" line="101"/>
        <source>Flatness δ
(ratio)</source>
        <translation>平面性 δ
(比)</translation>
    </message>
    <message>
        <location filename="../views/quality_colours.cpp" line="103"/>
        <source>Angle defect |K|
(rad)</source>
        <translation>角度欠損 |K|
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
        <translation>固定した頂点 %1 と %2 は、シート上でそれらを結ぶ直線に沿った距離だけ離れているため、その直線はまっすぐのままで、直線が載るストリップは平らなままです。平らなストリップに接する曲線の折り線は折れません (シートを折るには、どちらかの固定を解除してください)</translation>
    </message>
</context>
<context>
    <name>SmoothRulingsCommand</name>
    <message>
        <location filename="../model/document/commands/smooth_rulings_command.cpp" line="9"/>
        <source>Select at least one ruling between two patches.</source>
        <translation>2 つのパッチの間の母線を 1 本以上選択してください。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/smooth_rulings_command.cpp" line="19"/>
        <source>Edge %1 does not exist.</source>
        <translation>辺 %1 は存在しません。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/smooth_rulings_command.cpp" line="23"/>
        <source>Edge %1 is a curve; only rulings between two patches are smooth or sharp (curves take a crease condition).</source>
        <translation>辺 %1 は曲線です。滑らか・鋭角を設定できるのは 2 つのパッチの間の母線だけです (曲線には折り線の条件を設定します)。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/smooth_rulings_command.cpp" line="29"/>
        <source>Edge %1 is a ruling on the boundary; only rulings between two patches are smooth or sharp.</source>
        <translation>辺 %1 は境界上の母線です。滑らか・鋭角を設定できるのは 2 つのパッチの間の母線だけです。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/smooth_rulings_command.cpp" line="36"/>
        <source>The selected rulings are already smooth.</source>
        <translation>選択した母線はすでに滑らかです。</translation>
    </message>
    <message>
        <location filename="../model/document/commands/smooth_rulings_command.cpp" line="37"/>
        <source>The selected rulings are already sharp.</source>
        <translation>選択した母線はすでに鋭角です。</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/smooth_rulings_command.cpp" line="39"/>
        <source>Make %n rulings smooth</source>
        <translation>
            <numerusform>%n 本の母線を滑らかにする</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../model/document/commands/smooth_rulings_command.cpp" line="40"/>
        <source>Make %n rulings sharp</source>
        <translation>
            <numerusform>%n 本の母線を鋭角にする</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SplitAtRulingCommand</name>
    <message>
        <location filename="../model/document/commands/split_at_ruling_command.cpp" line="12"/>
        <source>Add a ruling across patch %1</source>
        <translation>パッチ %1 を横切る母線を追加</translation>
    </message>
    <message>
        <location filename="../model/document/commands/split_at_ruling_command.cpp" line="14"/>
        <source>No ruling can be added across patch %1</source>
        <translation>パッチ %1 を横切る母線は追加できません</translation>
    </message>
</context>
<context>
    <name>SubdivideStripCommand</name>
    <message>
        <location filename="../model/document/commands/subdivide_strip_command.cpp" line="9"/>
        <source>Add a crease across patch %1</source>
        <translation>パッチ %1 を横切る折り線を追加</translation>
    </message>
    <message>
        <location filename="../model/document/commands/subdivide_strip_command.cpp" line="11"/>
        <source>No crease can be added across patch %1</source>
        <translation>パッチ %1 を横切る折り線は追加できません</translation>
    </message>
</context>
<context>
    <name>SurfaceEditCommand</name>
    <message>
        <location filename="../model/document/commands/surface_edit_command.cpp" line="50"/>
        <source>There is no surface number %1 in the design.</source>
        <translation>デザインに曲面 %1 はありません。</translation>
    </message>
</context>
<context>
    <name>VerdictText</name>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="26"/>
        <source>patch %1</source>
        <translation>パッチ %1</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="27"/>
        <source>patches %1</source>
        <translation>パッチ %1</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="29"/>
        <source>surface %1 %2</source>
        <translation>曲面 %1 %2</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="38"/>
        <source>undo the last step and make a smaller change</source>
        <translation>最後の操作を元に戻して小さく変更する</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="41"/>
        <source>solve with more iterations</source>
        <translation>反復回数を増やしてソルブする</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="44"/>
        <source>release pins that hold the sheet</source>
        <translation>シートを押さえている固定を解除する</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="47"/>
        <source>solve again</source>
        <translation>もう一度ソルブする</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="49"/>
        <source>; or </source>
        <translation>、または</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="56"/>
        <source>&lt; 0.0001</source>
        <translation>&lt; 0.0001</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="66"/>
        <source>Developable to the tolerance — ready to cut.</source>
        <translation>許容値の範囲で可展 — 切り出せます。</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="69"/>
        <source>Developable to within %1 mm of isometry over the sheet: the cut pattern is off by at most %1 mm.</source>
        <translation>シート全体で等長から %1 mm 以内の可展: 型紙のずれは最大 %1 mm です。</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="76"/>
        <source>Developable patch by patch, but the development overlaps itself at %1: it cannot be cut from one piece. Try: %2.</source>
        <translation>パッチごとには可展ですが、展開図が %1 で自身と重なっています: 1 枚から切り出せません。試すこと: %2。</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="81"/>
        <source>Not developable: the surface folds over or its development overlaps itself</source>
        <translation>可展ではありません: 曲面が自身の上に折り返されているか、展開図が自身と重なっています</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="84"/>
        <source>Not developable from its sheet: it lies %1 mm from the sheet it keeps</source>
        <translation>保持しているシートから展開できません: シートから %1 mm 離れています</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="86"/>
        <location filename="../app/text/verdict_text.cpp" line="107"/>
        <source>Not developable</source>
        <translation>可展ではありません</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="87"/>
        <source>%1. Try: %2.</source>
        <translation>%1。試すこと: %2。</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="88"/>
        <source>%1 at %2. Try: %3.</source>
        <translation>%1 (%2)。試すこと: %3。</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="99"/>
        <source>Developable — ready to cut</source>
        <translation>可展 — 切り出せます</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="101"/>
        <source>Developable within %1 mm</source>
        <translation>%1 mm 以内で可展</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="105"/>
        <source>Development overlaps itself: %1</source>
        <translation>展開図が自身と重なっています: %1</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="107"/>
        <source>Not developable: %1</source>
        <translation>可展ではありません: %1</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="117"/>
        <source>Largest constraint residual %1 (tolerance %2).</source>
        <translation>制約の最大残差 %1 (許容値 %2)。</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="122"/>
        <source>Development: largest relative edge-length error %1 over a sheet of %2 mm, %3 mm from isometric.</source>
        <translation>展開図: 辺の長さの最大相対誤差 %1、シートの大きさ %2 mm、等長から %3 mm。</translation>
    </message>
    <message>
        <location filename="../app/text/verdict_text.cpp" line="131"/>
        <source>Distance from the sheet it keeps: %1 mm.</source>
        <translation>保持しているシートからの距離: %1 mm。</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ApproximateDialog</name>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="29"/>
        <source>Approximate Reference Shape</source>
        <translation>参照形状を近似</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/approximate_dialog.cpp" line="36"/>
        <source>%1 (%n point(s))</source>
        <translation>
            <numerusform>%1 (%n 点)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="40"/>
        <source>Reference &amp;shape:</source>
        <translation>参照形状(&amp;S):</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="44"/>
        <source>&amp;New strips:</source>
        <translation>新しいストリップ(&amp;N):</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="46"/>
        <source>Lay as many flat strips over patches of the shape (k-means clusters; where the shape curves both ways, bands twice as long as wide), pull them towards the shape and add them to the design. A strip that cannot follow the shape and stay developable is pulled again, damped, from the cylinder that fits its points best. Then each is trimmed back where it stands off the shape.</source>
        <translation>形状の同数の領域 (k-means クラスタ。形状が二方向に曲がるところでは幅の 2 倍の長さの帯) に平らなストリップを置き、形状へ引き寄せてデザインに追加します。形状に沿いつつ可展のままでいられないストリップは、点に最もよく合う円柱から減衰させて引き寄せ直します。その後、形状から離れて張り出した部分を切り詰めます。</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="56"/>
        <source>As &amp;one surface where the shape allows</source>
        <translation>形状が許す場合は一つの曲面として(&amp;O)</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="56"/>
        <source>Over a shape seen from one side (a panel), lay the new strips side by side as one watertight surface, bent to the shape, each two sharing a curve along which they may kink; around a shape that closes around an axis (a tube, a vase, a sphere), lay them as rings one after another, one surface open only at its two ends. Off, or over any other shape: separate strips over patches of the shape.</source>
        <translation>片側から見える形状(パネル)の上では、新しいストリップを横に並べて一つの水密な曲面として敷き、形状に沿って曲げ、隣り合う二つは折れ曲がってよい曲線を共有します。軸の周りに閉じた形状(筒、花瓶、球)の周りでは、リングとして順に敷き、両端だけが開いた一つの曲面にします。オフ、またはその他の形状では、形状のパッチごとに別々のストリップを敷きます。</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="56"/>
        <source>The &amp;design&apos;s surfaces</source>
        <translation>デザインの曲面(&amp;D)</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="58"/>
        <source>Pull the surfaces of the design towards the shape; each is pulled by the points nearest to it.</source>
        <translation>デザインの曲面を形状へ引き寄せます。各曲面はそれに最も近い点に引かれます。</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="65"/>
        <source>The design has no surface yet.</source>
        <translation>デザインにはまだ曲面がありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="71"/>
        <source>Start from:</source>
        <translation>開始:</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="77"/>
        <source>Spline intervals along each new strip: more follow finer detail and take longer.</source>
        <translation>新しい各ストリップに沿ったスプライン区間: 多いほど細部に追従しますが時間がかかります。</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="79"/>
        <source>&amp;Intervals per strip:</source>
        <translation>ストリップごとの区間(&amp;I):</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="89"/>
        <source>Iterations of the pull towards the shape; a few more follow in which the pull fades.</source>
        <translation>形状へ引き寄せる反復回数。その後、引力が弱まる反復が数回続きます。</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="91"/>
        <source>I&amp;terations:</source>
        <translation>反復回数(&amp;T):</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="95"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="96"/>
        <source>Thinning radius ρ: the shape is thinned to points at least ρ apart, each with the normal of the points around it.</source>
        <translation>間引き半径 ρ: 形状を互いに ρ 以上離れた点に間引き、各点に周囲の点の法線を付けます。</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="98"/>
        <source>Thinning radius &amp;ρ:</source>
        <translation>間引き半径 ρ(&amp;R):</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="107"/>
        <source>&amp;Approximate</source>
        <translation>近似(&amp;A)</translation>
    </message>
    <message>
        <location filename="../app/gui/approximate_dialog.cpp" line="133"/>
        <source>Default: %1 % of the shape&apos;s bounding-box diagonal (%2), or more where its points are sparse.</source>
        <translation>既定値: 形状のバウンディングボックス対角線 (%2) の %1 %、点がまばらな場合はそれ以上。</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ApproximateReaction</name>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="50"/>
        <source>Approximate Reference Shape</source>
        <translation>参照形状を近似</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="88"/>
        <source>Fit developable strips to a reference shape: import one first (File ▸ Import Reference Shape…).</source>
        <translation>参照形状に可展ストリップを当てはめます: まず読み込んでください (ファイル ▸ 参照形状をインポート…)。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="90"/>
        <source>Fit developable strips to a reference shape: wait until the solver has finished, or cancel it (Esc).</source>
        <translation>参照形状に可展ストリップを当てはめます: ソルバーの終了を待つか、中止してください (Esc)。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="92"/>
        <source>Fit developable strips to a reference shape, or pull the design&apos;s surfaces towards it; one undo step.</source>
        <translation>参照形状に可展ストリップを当てはめるか、デザインの曲面をそれへ引き寄せます。元に戻す操作は 1 回です。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="126"/>
        <source>Preparing the approximation: thinning the reference shape and placing the strips…</source>
        <translation>近似を準備中: 参照形状を間引いてストリップを配置しています…</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="153"/>
        <source>Approximation cancelled; the design is unchanged.</source>
        <translation>近似を中止しました。デザインは変更されていません。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="168"/>
        <source>Thinning the reference shape with radius %1 kept %n point(s), too few for the strips asked for; choose a smaller radius or fewer strips.</source>
        <translation>
            <numerusform>半径 %1 で参照形状を間引いた結果 %n 点しか残らず、指定したストリップ数には足りません。半径を小さくするか、ストリップを減らしてください。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="174"/>
        <source>The points of the reference shape lie on a line; no strip can be fitted to them.</source>
        <translation>参照形状の点が一直線上にあるため、ストリップを当てはめられません。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="178"/>
        <source>No surface of the design is near enough to the reference shape to be pulled towards it; start from new strips instead.</source>
        <translation>参照形状へ引き寄せられるほど近いデザインの曲面がありません。代わりに新しいストリップから始めてください。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="159"/>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="182"/>
        <source>Cannot approximate the reference shape</source>
        <translation>参照形状を近似できません</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="157"/>
        <source>The approximation could not be set up: %1</source>
        <translation>近似を準備できませんでした: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="187"/>
        <source>Approximation discarded: the design changed meanwhile; it is unchanged.</source>
        <translation>近似を破棄しました: その間にデザインが変更されました。デザインは変更されていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="201"/>
        <source>Measuring the distance of the result to the reference shape…</source>
        <translation>結果と参照形状の距離を測定中…</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="238"/>
        <source>%1 failed: %2 The design is unchanged.</source>
        <translation>%1 に失敗しました: %2 デザインは変更されていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="278"/>
        <source>largest constraint residual %1, within the tolerance</source>
        <translation>最大の制約残差 %1、許容範囲内</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="279"/>
        <source>largest constraint residual %1, not within the tolerance (Tools ▸ Solve may help)</source>
        <translation>最大の制約残差 %1、許容範囲外 (ツール ▸ ソルブが役立つ場合があります)</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="285"/>
        <source>the reference shape is %1 from the %n surface(s) on average, %2 at most</source>
        <translation>
            <numerusform>参照形状と %n 個の曲面の距離は平均 %1、最大 %2</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="289"/>
        <source>Approximated: %1; %2.</source>
        <translation>近似しました: %1。%2。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="290"/>
        <source>Afterwards %1.</source>
        <translation>近似後: %1。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="292"/>
        <source>Approximated with %n surface(s): %1.</source>
        <translation>
            <numerusform>%n 個の曲面で近似しました: %1。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="295"/>
        <source>%n surface(s) too far from the shape were left as they were.</source>
        <translation>
            <numerusform>形状から遠すぎる %n 個の曲面はそのままです。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="290"/>
        <source>The reference shape closes around an axis: its %n strip(s) were laid as rings one after another around it, one surface open only at its two ends.</source>
        <translation>
            <numerusform>参照形状は軸の周りに閉じています。その %n 本のストリップをリングとして順に周りに敷き、両端だけが開いた一つの曲面にしました。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="290"/>
        <source>The reference shape is one patch: its %n strip(s) were laid side by side as one watertight surface.</source>
        <translation>
            <numerusform>参照形状は一つのパッチです。%n 本のストリップを並べて一つの水密な曲面として配置しました。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="290"/>
        <source>Pulled closer, the surface did not end developable; it was kept as it was laid, bent to the shape.</source>
        <translation>近づけると曲面が可展にならなかったため、形状に沿って曲げて配置したままにしました。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="290"/>
        <source>%n strip(s) were trimmed back where they stood off the shape.</source>
        <translation>
            <numerusform>形状から離れていた %n 本のストリップを切り詰めました。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="290"/>
        <source>%n strip(s) could not be pulled closer and stay developable; they were kept as they were laid.</source>
        <translation>
            <numerusform>%n 本のストリップは可展性を保ったまま近づけられなかったため、配置したままにしました。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/approximate_reaction.cpp" line="302"/>
        <source>Set up in %1 s, solved in %2 s, measured in %3 s.</source>
        <translation>準備 %1 秒、求解 %2 秒、測定 %3 秒。</translation>
    </message>
</context>
<context>
    <name>devsurf::app::BackgroundRead</name>
    <message>
        <location filename="../app/gui/reactions/background_read.cpp" line="36"/>
        <source>Cancel</source>
        <translation>キャンセル</translation>
    </message>
</context>
<context>
    <name>devsurf::app::CameraActions</name>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="23"/>
        <source>&amp;Reset View</source>
        <translation>ビューをリセット(&amp;R)</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="26"/>
        <source>Reset View (Home): the starting direction, the whole design in view</source>
        <translation>ビューをリセット (Home): 初期の向きで、デザイン全体を表示</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="31"/>
        <source>&amp;Standard Views</source>
        <translation>標準ビュー(&amp;S)</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="42"/>
        <source>&amp;Isometric</source>
        <translation>等角(&amp;I)</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="43"/>
        <source>Isometric view (0): from the front right and above</source>
        <translation>等角ビュー (0): 右前上方から</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="45"/>
        <source>&amp;Front</source>
        <translation>正面(&amp;F)</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="45"/>
        <source>Front view (1): looking along +y</source>
        <translation>正面ビュー (1): +y 方向を見る</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="47"/>
        <source>&amp;Top</source>
        <translation>上面(&amp;T)</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="47"/>
        <source>Top view (2): looking down along −z</source>
        <translation>上面ビュー (2): −z 方向に見下ろす</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="49"/>
        <source>&amp;Right</source>
        <translation>右側面(&amp;R)</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="49"/>
        <source>Right view (3): looking along −x</source>
        <translation>右側面ビュー (3): −x 方向を見る</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="51"/>
        <source>R&amp;ear</source>
        <translation>背面(&amp;E)</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="51"/>
        <source>Rear view (4): looking along −y</source>
        <translation>背面ビュー (4): −y 方向を見る</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="53"/>
        <source>&amp;Bottom</source>
        <translation>下面(&amp;B)</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="53"/>
        <source>Bottom view (5): looking up along +z</source>
        <translation>下面ビュー (5): +z 方向に見上げる</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="55"/>
        <source>&amp;Left</source>
        <translation>左側面(&amp;L)</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="55"/>
        <source>Left view (6): looking along +x</source>
        <translation>左側面ビュー (6): +x 方向を見る</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="79"/>
        <source>Patch &amp;Numbers</source>
        <translation>パッチ番号(&amp;N)</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="81"/>
        <source>Ctrl+Shift+N</source>
        <translation>Ctrl+Shift+N</translation>
    </message>
    <message>
        <location filename="../app/gui/camera_actions.cpp" line="82"/>
        <source>Patch Numbers (Ctrl+Shift+N): write each patch&apos;s number on it</source>
        <translation>パッチ番号 (Ctrl+Shift+N): 各パッチにその番号を表示</translation>
    </message>
</context>
<context>
    <name>devsurf::app::CreaseConditionReaction</name>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="70"/>
        <source>Curved fold: the solver keeps the crease&apos;s osculating plane halfway between the two patches, so that the design folds from one flat sheet.</source>
        <translation>曲線折り: ソルバーは折り線の接触平面を 2 つのパッチの中間に保ち、デザインが 1 枚の平らなシートから折れるようにします。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="74"/>
        <source>Geodesic: the solver keeps the crease a geodesic of both patches.</source>
        <translation>測地線: ソルバーは折り線を両方のパッチの測地線に保ちます。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="77"/>
        <source>Straight when unfolded: the solver keeps the crease a straight line in the development.</source>
        <translation>展開で直線: ソルバーは折り線を展開図の上で直線に保ちます。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="83"/>
        <source>No condition: the solver treats the crease freely.</source>
        <translation>条件なし: ソルバーは折り線を自由に扱います。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="104"/>
        <source>Select creases (curves between two patches) of one surface first.</source>
        <translation>先に 1 つの曲面の折り線 (2 つのパッチの間の曲線) を選択してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="163"/>
        <source>Cr&amp;ease</source>
        <translation>折り線(&amp;E)</translation>
    </message>
</context>
<context>
    <name>devsurf::app::DeleteSelectionReaction</name>
    <message>
        <location filename="../app/gui/reactions/edit_reactions.cpp" line="10"/>
        <source>Deleting parts of a surface is not available yet: relabel an edge (Ctrl+L) or undo (Ctrl+Z) instead.</source>
        <translation>曲面の一部の削除はまだできません。代わりに辺のラベルを変更する (Ctrl+L) か、元に戻して (Ctrl+Z) ください。</translation>
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
        <translation>平均</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="52"/>
        <source>95th percentile</source>
        <translation>95 パーセンタイル</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="53"/>
        <source>Largest</source>
        <translation>最大</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="54"/>
        <source>Reference shape → design</source>
        <translation>参照形状 → デザイン</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="55"/>
        <source>Design → reference shape</source>
        <translation>デザイン → 参照形状</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="82"/>
        <source>Distance to Reference</source>
        <translation>参照形状までの距離</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="149"/>
        <source>The project has no reference shape; import one with File ▸ Import Reference Shape….</source>
        <translation>プロジェクトに参照形状がありません。ファイル ▸ 参照形状を読み込む… で読み込んでください。</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="151"/>
        <location filename="../app/gui/distance_report_dialog.cpp" line="157"/>
        <source>The design has no surface to measure.</source>
        <translation>デザインに計測する曲面がありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="153"/>
        <source>Measuring the distance between the design and the reference shapes…</source>
        <translation>デザインと参照形状の距離を計測しています…</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="155"/>
        <source>A surface of the design is not valid; solve or undo, then measure again.</source>
        <translation>デザインの曲面が有効ではありません。ソルブするか元に戻してから、もう一度計測してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="159"/>
        <source>The design changed: measuring again. The figures below are out of date.</source>
        <translation>デザインが変更されました。計測し直しています。下の数値は古いものです。</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="162"/>
        <source>Measured in %1 s.</source>
        <translation>%1 秒で計測しました。</translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="186"/>
        <source>Reference shape %1</source>
        <translation>参照形状 %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/distance_report_dialog.cpp" line="193"/>
        <source>Coverage: %1 of the %n point(s) lie within %2 of the design.</source>
        <translation>
            <numerusform>被覆率: %n 点のうち %1 がデザインから %2 以内にあります。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/distance_report_dialog.cpp" line="203"/>
        <source>Two-sided (Hausdorff) distance %1; bounding-box diagonal %2; the design sampled every %3.</source>
        <translation>両側 (ハウスドルフ) 距離 %1、バウンディングボックスの対角線 %2、デザインのサンプル間隔 %3。</translation>
    </message>
</context>
<context>
    <name>devsurf::app::DistanceReportReaction</name>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="174"/>
        <source>Measure how far the design is from a reference shape: import one first (File ▸ Import Reference Shape…).</source>
        <translation>デザインが参照形状からどれだけ離れているかを計測します。先に参照形状を読み込んでください (ファイル ▸ 参照形状を読み込む…)。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="176"/>
        <source>Measure how far the design is from the reference shapes: the design has no surface yet.</source>
        <translation>デザインが参照形状からどれだけ離れているかを計測します。デザインにまだ曲面がありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="178"/>
        <source>Show how far the design is from each reference shape, both ways (mean, 95th percentile, largest), and how much of the shape it covers.</source>
        <translation>デザインが各参照形状からどれだけ離れているかを両方向 (平均、95 パーセンタイル、最大) で示し、形状のどれだけを覆っているかを示します。</translation>
    </message>
</context>
<context>
    <name>devsurf::app::DragTool</name>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="20"/>
        <source>Drag cancelled; the design is as it was.</source>
        <translation>ドラッグを取り消しました。デザインは元のままです。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_text.cpp" line="16"/>
        <source>Drag %n vertices</source>
        <translation>
            <numerusform>%n 個の頂点をドラッグ</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_sheet.cpp" line="146"/>
        <source>Drag vertex %1 in the sheet</source>
        <translation>シート上で頂点 %1 をドラッグ</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_sheet.cpp" line="148"/>
        <source>Drag %n vertices in the sheet</source>
        <translation>
            <numerusform>シート上で %n 個の頂点をドラッグ</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_sheet.cpp" line="155"/>
        <source>Dragging %n vertices %1 mm along their sheet; the surface follows. Release to finish, Esc cancels.</source>
        <translation>
            <numerusform>%n 個の頂点をシート上で %1 mm ドラッグ中。曲面が追従します。離すと確定、Esc で取り消し。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_sheet.cpp" line="160"/>
        <source>Dragging vertex %1 %2 mm along its sheet; the surface follows. Release to finish, Esc cancels.</source>
        <translation>頂点 %1 をシート上で %2 mm ドラッグ中。曲面が追従します。離すと確定、Esc で取り消し。</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="51"/>
        <source>Sliding crease %1 by %2 mm within the surface, as far as it goes: the patch it moves into keeps %3 % of its width. Release to finish, Esc cancels.</source>
        <translation>折り線 %1 を曲面の中で %2 mm 移動中 (これ以上は動きません。移動先のパッチは幅の %3 % を保ちます)。離すと終了、Esc で取り消し。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_text.cpp" line="73"/>
        <source>Dragging %n vertices %1 mm along X. Release to finish, Esc cancels.</source>
        <translation>
            <numerusform>%n 個の頂点を X 方向に %1 mm ドラッグ中。離すと確定、Esc で取り消し。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_text.cpp" line="76"/>
        <source>Dragging %n vertices %1 mm along Y. Release to finish, Esc cancels.</source>
        <translation>
            <numerusform>%n 個の頂点を Y 方向に %1 mm ドラッグ中。離すと確定、Esc で取り消し。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_text.cpp" line="79"/>
        <source>Dragging %n vertices %1 mm along Z. Release to finish, Esc cancels.</source>
        <translation>
            <numerusform>%n 個の頂点を Z 方向に %1 mm ドラッグ中。離すと確定、Esc で取り消し。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/drag_tool_text.cpp" line="84"/>
        <source>Dragging %n vertices %1 mm in the view plane. Release to finish, Esc cancels; hold X, Y or Z to move along that axis.</source>
        <translation>
            <numerusform>%n 個の頂点を視平面内で %1 mm ドラッグ中。離すと確定、Esc で取り消し。X、Y、Z を押し続けるとその軸に沿って動きます。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_sheet.cpp" line="26"/>
        <source>Points of the development can be dragged only where the surface holds its sheet (Tools ▸ Hold the Sheet).</source>
        <translation>展開図の点をドラッグできるのは、曲面がシートを保持しているときだけです (ツール ▸ シートを保持)。</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool.cpp" line="200"/>
        <source>Vertex %1 is pinned and cannot be dragged; unpin it first.</source>
        <translation>頂点 %1 は固定されているためドラッグできません。先に固定を解除してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool.cpp" line="209"/>
        <location filename="../app/gui/drag_tool.cpp" line="252"/>
        <location filename="../app/gui/drag_tool_sheet.cpp" line="51"/>
        <source>a drag started</source>
        <translation>ドラッグが始まりました</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool.cpp" line="235"/>
        <source>There is no edge %1.</source>
        <translation>辺 %1 はありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool.cpp" line="238"/>
        <source>Edge %1 is not a crease (a curve between two patches); only creases can be dragged.</source>
        <translation>辺 %1 は折り線 (2 つのパッチの間の曲線) ではありません。ドラッグできるのは折り線だけです。</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool.cpp" line="243"/>
        <source>Edge %1 cannot move: both its ends are pinned and it has no other control point.</source>
        <translation>辺 %1 は動かせません: 両端が固定されていて、ほかに制御点がありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool.cpp" line="312"/>
        <source>Snapped to reference curve %1.</source>
        <translation>参照曲線 %1 にスナップしました。</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="96"/>
        <source>Pins %1 and %2 hold vertex %3 on the straight line between them (they are as far apart as in the flat sheet): it moves only by stretching the sheet. </source>
        <translation>固定点 %1 と %2 が頂点 %3 をその間の直線上に押さえています (2 点の距離は平らなシートと同じ)。シートを伸ばさなければ動きません。</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="102"/>
        <source>Pins %1, %2 and %3 hold vertex %4 in the triangle between them (they are as far apart as in the flat sheet): it moves only by stretching the sheet. </source>
        <translation>固定点 %1、%2、%3 が頂点 %4 をその三角形の中に押さえています (距離は平らなシートと同じ)。シートを伸ばさなければ動きません。</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="31"/>
        <source>Drag stopped: %1 The design is as it was.</source>
        <translation>ドラッグを中止しました: %1 デザインは元のままです。</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="14"/>
        <source>Drag crease %1</source>
        <translation>折り線 %1 をドラッグ</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="24"/>
        <source>%1: settling, iteration %2 of %3 (Esc cancels).</source>
        <translation>%1: 収束中、反復 %2 / %3 (Esc で取り消し)。</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="35"/>
        <source>Drag tool: press on a vertex in the 3D view and move the mouse; the selected vertices of its surface follow. Press on a crease to slide it within its patches. Esc cancels a drag.</source>
        <translation>ドラッグツール: 3D ビューで頂点を押してマウスを動かすと、その曲面の選択した頂点が追従します。折り線を押すと、パッチの中で折り線を滑らせます。Esc でドラッグを取り消します。</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="41"/>
        <source>Drag stopped: the design changed during the drag.</source>
        <translation>ドラッグを中止しました: ドラッグ中にデザインが変更されました。</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="59"/>
        <source>Sliding crease %1 by %2 mm within the surface. Release to finish, Esc cancels; hold X, Y or Z to move along that axis.</source>
        <translation>折り線 %1 を曲面の中で %2 mm 移動中。離すと終了、Esc で取り消し。X、Y、Z を押したままにするとその軸に沿って動きます。</translation>
    </message>
    <message>
        <location filename="../app/gui/drag_tool_text.cpp" line="63"/>
        <source>Moving crease %1 by %2 mm along the axis. Release to finish, Esc cancels.</source>
        <translation>折り線 %1 を軸に沿って %2 mm 移動中。離すと終了、Esc で取り消し。</translation>
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
        <translation>元のシートを保持(&amp;H)</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="25"/>
        <source>New from Example</source>
        <translation>例から新規作成</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="33"/>
        <source>&amp;Example:</source>
        <translation>例(&amp;E):</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="34"/>
        <source>&amp;Size:</source>
        <translation>サイズ(&amp;S):</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="65"/>
        <source>Keep the development around the cylinder the design&apos;s unfolding rolls onto, as Tools ▸ Hold the Sheet does: a drag that the sheet cannot follow lags behind the mouse instead of stretching it.</source>
        <translation>ツール ▸ シートを保持 と同じように、デザインの展開図が巻き付く円柱の周りに展開図を保ちます: シートが追従できないドラッグは、シートを伸ばす代わりにマウスより遅れます。</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="68"/>
        <source>Keep the development: the design stays foldable from the flat sheet it starts as, and a drag that the sheet cannot follow lags behind the mouse instead of stretching it. Of two pins at the ends of a straight line in the sheet only the first stays pinned, since the sheet would keep that line straight. Tools ▸ Hold the Sheet turns it off later.</source>
        <translation>展開図を保持します: デザインは元の平らなシートから折れるままで、シートが追従できないドラッグは、シートを伸ばす代わりにマウスより遅れます。シート上の直線の両端にある2つのピンは、最初のものだけがピン留めのまま残ります (シートがその直線をまっすぐに保つため)。後で ツール ▸ シートを保持 でオフにできます。</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="75"/>
        <source>This example comes holding its sheet.</source>
        <translation>この例は最初からシートを保持しています。</translation>
    </message>
    <message>
        <location filename="../app/gui/example_dialog.cpp" line="79"/>
        <source>A torus unfolds into no one sheet: it keeps local conditions only.</source>
        <translation>トーラスは1枚のシートに展開できません: 局所的な条件だけを保ちます。</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ExportJsonReaction</name>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="96"/>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="113"/>
        <source>Export Interchange JSON</source>
        <translation>交換用 JSON のエクスポート</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="97"/>
        <source>“%1” ends in .%2, but this command writes interchange JSON. Export to “%3” instead?</source>
        <translation>「%1」の拡張子は .%2 ですが、このコマンドは交換用 JSON を書き出します。代わりに「%3」にエクスポートしますか?</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="102"/>
        <source>Export as .json</source>
        <translation>.json としてエクスポート</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="111"/>
        <source>untitled</source>
        <translation>無題</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="115"/>
        <source>Interchange JSON (*.json)</source>
        <translation>交換用 JSON (*.json)</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="128"/>
        <source>Exported %1</source>
        <translation>%1 をエクスポートしました</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="123"/>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="130"/>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="133"/>
        <source>Export failed</source>
        <translation>エクスポートに失敗しました</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="134"/>
        <source>The design cannot be exported: %1</source>
        <translation>デザインをエクスポートできません: %1</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ExportPatternReaction</name>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="84"/>
        <source>untitled</source>
        <translation>無題</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="89"/>
        <source>Exported the cutting pattern</source>
        <translation>型紙をエクスポートしました</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ExportShapeReaction</name>
    <message>
        <location filename="../app/gui/reactions/shape_reactions.cpp" line="23"/>
        <source>untitled</source>
        <translation>無題</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/shape_reactions.cpp" line="28"/>
        <source>Exported the 3D shape (%1)</source>
        <translation>3D 形状をエクスポートしました (%1)</translation>
    </message>
</context>
<context>
    <name>devsurf::app::FitEdgeToCurveReaction</name>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="185"/>
        <source>Lay a crease or boundary onto a reference curve: import curves first (File ▸ Import Curves…).</source>
        <translation>折り目または境界を参照曲線に合わせます: まず曲線を読み込んでください (ファイル ▸ 曲線を読み込む…)。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="187"/>
        <source>Lay a crease or boundary onto a reference curve: select one spline edge.</source>
        <translation>折り目または境界を参照曲線に合わせます: スプライン辺を 1 本選んでください。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="188"/>
        <source>Lay the selected crease or boundary onto the reference curve nearest it; Solve then makes the surface developable again.</source>
        <translation>選んだ折り目または境界を最も近い参照曲線に合わせます。その後ソルブで曲面を再び可展にします。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="211"/>
        <source>Edge %1 was not fitted: both its ends are nearest the same point of %2.</source>
        <translation>辺 %1 は合わせられませんでした: 両端が %2 の同じ点に最も近いためです。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="214"/>
        <source>Edge %1 was not fitted: %2 has too few points.</source>
        <translation>辺 %1 は合わせられませんでした: %2 の点が少なすぎます。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="218"/>
        <source>Fit Edge to Curve</source>
        <translation>辺を曲線に合わせる</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="220"/>
        <source>Cannot fit the edge to the curve</source>
        <translation>辺を曲線に合わせられません</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="225"/>
        <source>Edge %1 lies on %2 within %3 mm; Solve (Ctrl+Return) makes the surface developable again.</source>
        <translation>辺 %1 は %2 に %3 mm 以内で重なりました。ソルブ (Ctrl+Return) で曲面を再び可展にします。</translation>
    </message>
</context>
<context>
    <name>devsurf::app::HoldSheetReaction</name>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="79"/>
        <source>Hold the sheet of a surface: select something on one surface first.</source>
        <translation>曲面のシートを保持します: まず 1 つの曲面上の要素を選択してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="80"/>
        <source>The surface is folded from its sheet: solves and drags keep it isometric to its development, and a dragged vertex stays behind where the sheet cannot follow. Uncheck to let the sheet stretch again.</source>
        <translation>曲面はそのシートから折られています: ソルブとドラッグは展開図との等長性を保ち、シートが追従できない所ではドラッグした頂点が手前で止まります。チェックを外すとシートは再び伸びられます。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="83"/>
        <source>Fold the surface from its sheet: its development as it unfolds now is kept by every solve and drag; a dragged vertex stays behind where the sheet cannot follow, instead of the sheet stretching.</source>
        <translation>曲面をそのシートから折ります: 現在の展開図がすべてのソルブとドラッグで保たれ、シートが追従できない所では、シートが伸びる代わりにドラッグした頂点が手前で止まります。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="99"/>
        <source>Hold the Sheet</source>
        <translation>シートを保持</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="99"/>
        <source>Let the Sheet Stretch</source>
        <translation>シートの伸びを許す</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="102"/>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="113"/>
        <source>Cannot hold the sheet</source>
        <translation>シートを保持できません</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="113"/>
        <source>Cannot let the sheet stretch</source>
        <translation>シートの伸びを許せません</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ImportCurvesReaction</name>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="39"/>
        <source>%1 is not a file DevSurf reads curves from; choose a DXF, SVG, STEP or IGES file.</source>
        <translation>%1 は DevSurf が曲線を読み込めるファイルではありません。DXF、SVG、STEP または IGES ファイルを選んでください。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="42"/>
        <source>This build of DevSurf reads curves from DXF and SVG files only; save the curves as DXF.</source>
        <translation>この DevSurf は DXF と SVG ファイルからのみ曲線を読み込みます。曲線を DXF で保存してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="45"/>
        <source>%1 cannot be read; check that it exists and that you may read it.</source>
        <translation>%1 を読み込めません。ファイルが存在し、読み取り権限があるか確認してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="49"/>
        <source>%1 is too large to import curves from.</source>
        <translation>%1 は大きすぎて曲線を読み込めません。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="51"/>
        <source>%1 is damaged or not a valid file of its type; nothing was imported.</source>
        <translation>%1 は壊れているか、その形式の有効なファイルではありません。何も読み込んでいません。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="55"/>
        <source>%1 holds no lines, polylines, splines, arcs or circles to import.</source>
        <translation>%1 には読み込める線分、ポリライン、スプライン、円弧、円がありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="61"/>
        <source>The curves of %1 could not be imported.</source>
        <translation>%1 の曲線を読み込めませんでした。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="82"/>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="99"/>
        <source>Import Curves</source>
        <translation>曲線を読み込む</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="83"/>
        <source>Curve files (*.dxf *.svg *.step *.stp *.iges *.igs);;DXF (*.dxf);;SVG (*.svg);;STEP (*.step *.stp);;IGES (*.iges *.igs)</source>
        <translation>曲線ファイル (*.dxf *.svg *.step *.stp *.iges *.igs);;DXF (*.dxf);;SVG (*.svg);;STEP (*.step *.stp);;IGES (*.iges *.igs)</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="98"/>
        <source>Reading curves from %1…</source>
        <translation>%1 から曲線を読み込んでいます…</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="123"/>
        <source>Import of curves from %1 cancelled</source>
        <translation>%1 からの曲線の読み込みを中止しました</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="125"/>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="131"/>
        <source>Cannot import curves</source>
        <translation>曲線を読み込めません</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="133"/>
        <source>Imported the curves of %1</source>
        <translation>%1 の曲線を読み込みました</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ImportReferenceShapeReaction</name>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="81"/>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="99"/>
        <source>Import Reference Shape</source>
        <translation>参照形状を読み込む</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="83"/>
        <source>Meshes and point clouds (*.obj *.ply *.stl *.off *.xyz *.pts);;Meshes (*.obj *.ply *.stl *.off);;Point clouds (*.xyz *.pts)</source>
        <translation>メッシュと点群 (*.obj *.ply *.stl *.off *.xyz *.pts);;メッシュ (*.obj *.ply *.stl *.off);;点群 (*.xyz *.pts)</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="98"/>
        <source>Reading reference shape %1…</source>
        <translation>参照形状 %1 を読み込み中…</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="122"/>
        <source>Import of reference shape %1 cancelled</source>
        <translation>参照形状 %1 の読み込みを中止しました</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="124"/>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="133"/>
        <source>Cannot import the reference shape</source>
        <translation>参照形状を読み込めません</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="135"/>
        <source>Imported reference shape %1: %2, %3</source>
        <translation>参照形状 %1 を読み込みました: %2、%3</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="136"/>
        <source>%n point(s)</source>
        <translation>
            <numerusform>%n 点</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="137"/>
        <source>%n triangle(s)</source>
        <translation>
            <numerusform>%n 個の三角形</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::JoinReaction</name>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="41"/>
        <source>Join Surfaces</source>
        <translation>サーフェスを結合</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="81"/>
        <source>Join surfaces into one composite: wait until the solver has finished, or cancel it (Esc).</source>
        <translation>サーフェスを 1 つの複合サーフェスに結合します: ソルバーの終了を待つか、中止してください (Esc)。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="83"/>
        <source>Join the selected surfaces (all when fewer than two are selected) into one composite: boundary curves or rulings that face each other become shared edges, held to the reference shapes where there are any; one undo step.</source>
        <translation>選択したサーフェス (選択が 2 つ未満ならすべて) を 1 つの複合サーフェスに結合します: 向かい合う境界曲線または母線が共有エッジになり、参照形状があればそれに保持されます。元に戻す 1 ステップです。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="106"/>
        <source>Preparing the join: thinning the reference shapes…</source>
        <translation>結合を準備中: 参照形状を間引いています…</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="140"/>
        <source>Join cancelled; the design is unchanged.</source>
        <translation>結合を中止しました。デザインは変更されていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="144"/>
        <source>Join discarded: the design changed meanwhile; it is unchanged.</source>
        <translation>結合を破棄しました: その間にデザインが変更されました。デザインは変更されていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="79"/>
        <source>Join surfaces into one composite where their boundary edges face each other: the design needs at least two surfaces.</source>
        <translation>境界エッジが向かい合う箇所でサーフェスを 1 つの複合サーフェスに結合します: デザインに 2 つ以上のサーフェスが必要です。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="133"/>
        <source>The reference shapes could not be thinned for the join (%1); nothing was joined.</source>
        <translation>結合のために参照形状を間引けませんでした (%1)。何も結合されませんでした。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="135"/>
        <source>Cannot join the surfaces</source>
        <translation>サーフェスを結合できません</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/join_reaction.cpp" line="174"/>
        <source>No two of the %n surface(s) have boundary edges facing each other (within %1 % of their length); nothing was joined.</source>
        <translation>
            <numerusform>%n 個のサーフェスには互いに向かい合う境界エッジがありません (長さの %1 % 以内)。何も結合されませんでした。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="192"/>
        <source>%1 failed: %2 The design is unchanged.</source>
        <translation>%1 に失敗しました: %2 デザインは変更されていません。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/join_reaction.cpp" line="201"/>
        <source>Joined %n surface(s) into one: </source>
        <translation>
            <numerusform>%n 個のサーフェスを 1 つに結合しました: </numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/join_reaction.cpp" line="202"/>
        <source>%1 of %n pair(s) of facing edges welded</source>
        <translation>
            <numerusform>向かい合うエッジ %n 組のうち %1 組を溶接</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/join_reaction.cpp" line="203"/>
        <source>, %n part(s) not connected</source>
        <translation>
            <numerusform>、%n 個の部分は未接続</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="206"/>
        <source>largest constraint residual %1, within the tolerance.</source>
        <translation>最大の制約残差 %1、許容範囲内。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="207"/>
        <source>largest constraint residual %1, not within the tolerance (Tools ▸ Solve may help).</source>
        <translation>最大の制約残差 %1、許容範囲外 (ツール ▸ ソルブが役立つ場合があります)。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="211"/>
        <source>Not welded: %1</source>
        <translation>溶接されていません: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/join_reaction.cpp" line="215"/>
        <source>%n surface(s) facing no other were left as they are.</source>
        <translation>
            <numerusform>他と向かい合わない %n 個のサーフェスはそのままにしました。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/join_reaction.cpp" line="220"/>
        <source>The surfaces were held to the reference shape meanwhile.</source>
        <translation>その間、サーフェスは参照形状に保持されました。</translation>
    </message>
</context>
<context>
    <name>devsurf::app::MainWindow</name>
    <message>
        <location filename="../app/gui/main_window.cpp" line="127"/>
        <source>Patches</source>
        <translation>パッチ</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="133"/>
        <source>Properties</source>
        <translation>プロパティ</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="139"/>
        <source>Pins</source>
        <translation>固定点</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="149"/>
        <source>Solver</source>
        <translation>ソルバー</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="169"/>
        <source>Main</source>
        <translation>メイン</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="176"/>
        <source>&amp;File</source>
        <translation>ファイル(&amp;F)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="178"/>
        <source>&amp;New from Example…</source>
        <translation>例から新規作成(&amp;N)…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="180"/>
        <source>&amp;Open…</source>
        <translation>開く(&amp;O)…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="182"/>
        <source>Open &amp;Recent</source>
        <translation>最近使ったファイル(&amp;R)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="186"/>
        <source>&amp;Save</source>
        <translation>保存(&amp;S)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="189"/>
        <source>Save &amp;As…</source>
        <translation>名前を付けて保存(&amp;A)…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="193"/>
        <source>Import &amp;Curves…</source>
        <translation>曲線を読み込む(&amp;C)…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="195"/>
        <source>Add the curves of a DXF, SVG, STEP or IGES file as reference curves</source>
        <translation>DXF、SVG、STEP または IGES ファイルの曲線を参照曲線として加えます</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="198"/>
        <source>Import Reference S&amp;hape…</source>
        <translation>参照形状を読み込む(&amp;H)…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="199"/>
        <source>Add a mesh (OBJ, PLY, STL, OFF) or a point cloud (XYZ, PTS) the design is to follow, as a reference shape</source>
        <translation>デザインが従うべきメッシュ (OBJ、PLY、STL、OFF) または点群 (XYZ、PTS) を参照形状として追加</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="203"/>
        <source>&amp;Export Interchange JSON…</source>
        <translation>交換用 JSON をエクスポート(&amp;E)…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="203"/>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="206"/>
        <source>Export &amp;3D Shape…</source>
        <translation>3D 形状をエクスポート(&amp;3)…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="210"/>
        <source>&amp;Quit</source>
        <translation>終了(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="214"/>
        <source>&amp;Edit</source>
        <translation>編集(&amp;E)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="217"/>
        <source>&amp;Undo</source>
        <translation>元に戻す(&amp;U)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="220"/>
        <source>&amp;Redo</source>
        <translation>やり直す(&amp;R)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="227"/>
        <source>&amp;Delete</source>
        <translation>削除(&amp;D)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="230"/>
        <source>Remove Reference &amp;Curves</source>
        <translation>参照曲線を削除(&amp;C)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="233"/>
        <source>Remove Reference S&amp;hapes</source>
        <translation>参照形状を削除(&amp;H)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="235"/>
        <source>Select &amp;None</source>
        <translation>選択を解除(&amp;N)</translation>
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
        <translation>表示(&amp;V)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="242"/>
        <source>&amp;3D View</source>
        <translation>3D ビュー(&amp;3)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="242"/>
        <source>Ctrl+1</source>
        <translation>Ctrl+1</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="244"/>
        <source>&amp;Development View</source>
        <translation>展開図ビュー(&amp;D)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="244"/>
        <source>Ctrl+2</source>
        <translation>Ctrl+2</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="245"/>
        <source>3D &amp;and Development</source>
        <translation>3D と展開図(&amp;A)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="246"/>
        <source>Ctrl+3</source>
        <translation>Ctrl+3</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="250"/>
        <source>&amp;Control Polygons</source>
        <translation>制御多角形(&amp;C)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="250"/>
        <source>Ctrl+Shift+P</source>
        <translation>Ctrl+Shift+P</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="251"/>
        <source>&amp;Vertices</source>
        <translation>頂点(&amp;V)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="252"/>
        <source>Ctrl+Shift+V</source>
        <translation>Ctrl+Shift+V</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="255"/>
        <source>S&amp;heet Outline</source>
        <translation>シートの輪郭(&amp;H)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="258"/>
        <source>Draw the sheet a held development is confined to behind it in the development view (Tools ▸ Sheet Shape…).</source>
        <translation>保持した展開図を収めるシートを展開図ビューで展開図の後ろに描きます (ツール ▸ シートの形…)。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="268"/>
        <source>&amp;Reference Shapes</source>
        <translation>参照形状(&amp;R)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="271"/>
        <source>Draw the imported meshes and point clouds in the 3D view (File ▸ Import Reference Shape…).</source>
        <translation>読み込んだメッシュと点群を 3D ビューに描く (ファイル ▸ 参照形状を読み込む…)。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="282"/>
        <source>Colour Reference by Dis&amp;tance</source>
        <translation>参照形状を距離で色分け(&amp;T)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="320"/>
        <source>Remove Rulin&amp;g</source>
        <translation>母線を削除(&amp;G)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="320"/>
        <source>Ctrl+Alt+R</source>
        <translation>Ctrl+Alt+R</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="347"/>
        <source>Dis&amp;tance to Reference…</source>
        <translation>参照形状までの距離(&amp;T)…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="286"/>
        <source>Colour the points of the reference shapes by their distance to the design, in mm, with a legend (green: within the coverage tolerance of Tools ▸ Distance to Reference…).</source>
        <translation>参照形状の点をデザインまでの距離 (mm) で色分けし、凡例を表示します (緑: ツール ▸ 参照形状までの距離… の被覆許容差以内)。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="297"/>
        <source>&amp;Fit All</source>
        <translation>全体を表示(&amp;F)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="297"/>
        <source>F</source>
        <translation>F</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="303"/>
        <source>Reset &amp;Layout</source>
        <translation>レイアウトをリセット(&amp;L)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="308"/>
        <source>&amp;Tools</source>
        <translation>ツール(&amp;T)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="311"/>
        <source>&amp;Relabel Edge (R ↔ S)</source>
        <translation>辺のラベルを変更 (R ↔ S)(&amp;R)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="311"/>
        <source>Ctrl+L</source>
        <translation>Ctrl+L</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="313"/>
        <source>Add &amp;Crease…</source>
        <translation>折り線を追加(&amp;C)…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="314"/>
        <source>Ctrl+D</source>
        <translation>Ctrl+D</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="316"/>
        <source>Add R&amp;uling…</source>
        <translation>母線を追加(&amp;U)…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="317"/>
        <source>Ctrl+R</source>
        <translation>Ctrl+R</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="322"/>
        <source>Re&amp;fine Curves</source>
        <translation>曲線を細分化(&amp;F)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="323"/>
        <source>Ctrl+Shift+R</source>
        <translation>Ctrl+Shift+R</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="329"/>
        <source>&amp;Move or Rotate Vertices…</source>
        <translation>頂点の移動・回転(&amp;M)…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="329"/>
        <source>Ctrl+M</source>
        <translation>Ctrl+M</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="332"/>
        <source>&amp;Pin Vertices</source>
        <translation>頂点を固定(&amp;P)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="333"/>
        <source>Ctrl+K</source>
        <translation>Ctrl+K</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="335"/>
        <source>U&amp;npin Vertices</source>
        <translation>頂点の固定を解除(&amp;N)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="336"/>
        <source>Ctrl+Shift+K</source>
        <translation>Ctrl+Shift+K</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="339"/>
        <source>Hold the &amp;Sheet</source>
        <translation>シートを保持(&amp;S)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="340"/>
        <source>Ctrl+Shift+H</source>
        <translation>Ctrl+Shift+H</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="343"/>
        <source>Sheet S&amp;hape…</source>
        <translation>シートの形(&amp;H)…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="350"/>
        <source>A&amp;pproximate Reference Shape…</source>
        <translation>参照形状を近似(&amp;P)…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="358"/>
        <source>&amp;Join Surfaces</source>
        <translation>サーフェスを結合(&amp;J)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="359"/>
        <source>Ctrl+J</source>
        <translation>Ctrl+J</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="363"/>
        <source>Mar&amp;k Region of Reference Shape</source>
        <translation>参照形状の領域をマーク(&amp;K)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="363"/>
        <source>L</source>
        <translation>L</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="365"/>
        <source>Add Strip O&amp;ver Marked Region</source>
        <translation>マークした領域にストリップを追加(&amp;V)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="402"/>
        <source>&amp;Help</source>
        <translation>ヘルプ(&amp;H)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="403"/>
        <source>&amp;User Manual</source>
        <translation>ユーザーマニュアル(&amp;U)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="410"/>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>キーボードショートカット(&amp;K)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="416"/>
        <source>&amp;About DevSurf</source>
        <translation>DevSurf について(&amp;A)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="418"/>
        <source>About DevSurf</source>
        <translation>DevSurf について</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="419"/>
        <source>&lt;b&gt;DevSurf %1&lt;/b&gt;&lt;p&gt;Design of developable surfaces and curved-crease origami with spline developables (Tang, Bo, Wallner, Pottmann 2015).&lt;/p&gt;</source>
        <translation>&lt;b&gt;DevSurf %1&lt;/b&gt;&lt;p&gt;スプライン可展面による可展面と曲線折り折り紙の設計 (Tang, Bo, Wallner, Pottmann 2015)。&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="464"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="486"/>
        <source>Untitled</source>
        <translation>無題</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="487"/>
        <source>%1[*] — DevSurf</source>
        <translation>%1[*] — DevSurf</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/main_window.cpp" line="501"/>
        <source>%n surface(s)</source>
        <translation>
            <numerusform>曲面 %n 個</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/main_window.cpp" line="502"/>
        <source>%n patch(es)</source>
        <translation>
            <numerusform>パッチ %n 個</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/main_window.cpp" line="503"/>
        <source>%n control point(s)</source>
        <translation>
            <numerusform>制御点 %n 個</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/main_window.cpp" line="504"/>
        <source>%n selected</source>
        <translation>
            <numerusform>%n 個選択</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="30"/>
        <source>&amp;Solve</source>
        <translation>ソルブ(&amp;S)</translation>
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
            <numerusform>すべての曲面を可展面に戻します: ソルバーを %n 回反復し、1 回の取り消し操作にまとめます。固定した頂点は動きません。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="42"/>
        <source>Solver &amp;Iterations…</source>
        <translation>ソルバーの反復回数(&amp;I)…</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="44"/>
        <source>The most solver iterations Tools ▸ Solve runs; it stops earlier once the surface has converged.</source>
        <translation>ツール ▸ ソルブで実行する反復回数の上限。曲面が収束すればそれより前に終わります。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="49"/>
        <source>Solver Iterations</source>
        <translation>ソルバーの反復回数</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="49"/>
        <source>Most iterations of Tools ▸ Solve:</source>
        <translation>ツール ▸ ソルブの反復回数の上限:</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="82"/>
        <source>R&amp;otate Vertices</source>
        <translation>頂点を回転(&amp;O)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="83"/>
        <source>R</source>
        <translation>R</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="86"/>
        <source>Rotate tool (R): select two or more vertices, press on a vertex in the 3D view and move the mouse sideways; they turn about an axis through their centroid (vertical, or as chosen in the toolbar) and the surface follows. Esc cancels.</source>
        <translation>回転ツール (R): 2 個以上の頂点を選択し、3D ビューで頂点を押してマウスを横に動かすと、頂点が重心を通る軸 (鉛直、またはツールバーで選んだ軸) の周りに回転し、曲面が追従します。Esc で取り消します。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="95"/>
        <source>Measure tool: click two points of the surface in the 3D view; their distance in space and along the sheet (as the cut pattern has it) is drawn and shown in the status bar. Select an edge for its length, two edges that meet for their angle.</source>
        <translation>計測ツール: 3D ビューで曲面上の 2 点をクリックすると、空間での距離とシートに沿った距離 (型紙上の距離) が描かれ、ステータスバーに表示されます。辺を 1 本選ぶとその長さを、交わる 2 本の辺を選ぶとその角度を計測します。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="119"/>
        <source>Finish the drag first; it solves as it goes.</source>
        <translation>先にドラッグを終えてください。ドラッグ中も随時ソルブしています。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="58"/>
        <source>G</source>
        <translation>G</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="58"/>
        <source>&amp;Drag Vertices and Creases</source>
        <translation>頂点と折り線をドラッグ(&amp;D)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="61"/>
        <source>Drag tool: press on a vertex in the 3D view and move it, the surface follows and stays developable; press on a crease to slide it within its patches. The axis chosen in the toolbar, or holding X, Y or Z, moves along that axis; Esc cancels the drag (G).</source>
        <translation>ドラッグツール: 3D ビューで頂点を押して動かすと、曲面が追従して可展のまま保たれます。折り線を押すと、パッチの中で折り線を滑らせます。ツールバーで選んだ軸、または X、Y、Z を押したままにすると、その軸に沿って動きます。Esc でドラッグを取り消します (G)。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="70"/>
        <source>S&amp;nap to Reference Curves</source>
        <translation>参照曲線にスナップ(&amp;N)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="72"/>
        <source>While dragging a vertex (no axis chosen), put it on the nearest reference curve drawn within 10 pixels of the mouse.</source>
        <translation>頂点をドラッグするとき (軸の指定なし)、マウスから 10 ピクセル以内に描かれた最も近い参照曲線の上に置きます。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="78"/>
        <source>&amp;Fit Edge to Reference Curve</source>
        <translation>辺を参照曲線に合わせる(&amp;F)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="93"/>
        <source>Measur&amp;e</source>
        <translation>計測(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="101"/>
        <source>Cop&amp;y Measurement</source>
        <translation>計測値をコピー(&amp;Y)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="101"/>
        <source>Ctrl+C</source>
        <translation>Ctrl+C</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="102"/>
        <source>Copy the last measurement to the clipboard (Ctrl+C).</source>
        <translation>最後の計測値をクリップボードにコピーします (Ctrl+C)。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="127"/>
        <source>&amp;Cancel Solve</source>
        <translation>ソルブを中止(&amp;C)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="130"/>
        <source>Stop the running solve; the design stays as it is (Esc).</source>
        <translation>実行中のソルブを中止します。デザインはそのままです (Esc)。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="154"/>
        <source>Solving: iteration %1 of %2, residual %3</source>
        <translation>ソルブ中: 反復 %1 / %2、残差 %3</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="167"/>
        <source>&amp;Lengths While Dragging</source>
        <translation>ドラッグ中の長さ(&amp;L)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="179"/>
        <source>&amp;Automatic</source>
        <translation>自動(&amp;A)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="180"/>
        <source>Vertex drags and rotations keep lengths. Where the sheet cannot follow that way (the drag does not converge, folds over, collapses a strip or its development overlaps itself), the drag is replayed on release letting the sheet stretch, and the better of the two is kept; the Solver panel says so.</source>
        <translation>頂点のドラッグと回転は長さを保ちます。シートがそのままでは追従できない場合 (ドラッグが収束しない、折り返す、帯がつぶれる、または展開図が自身と重なる場合)、離したときにシートの伸びを許してドラッグをやり直し、二つのうち良い方を残します。ソルバーパネルにその旨が表示されます。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="184"/>
        <source>&amp;Keep Lengths</source>
        <translation>長さを保つ(&amp;K)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="185"/>
        <source>While dragging or rotating vertices, the sheet bends instead of stretching: far parts stay in place and curved creases keep their shape and fold. A motion the sheet cannot make without stretching then may not converge. Dragged creases always resize their patches.</source>
        <translation>頂点のドラッグや回転の間、シートは伸びずに曲がります。離れた部分はその場に留まり、曲がった折り線は形を保って折れます。シートが伸びずにはできない動きは収束しないことがあります。ドラッグした折り線は常にパッチの大きさを変えます。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="189"/>
        <source>Let &amp;Stretch</source>
        <translation>伸びを許す(&amp;S)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="190"/>
        <source>While dragging or rotating vertices, the sheet may stretch: it stays developable and its development changes, curved creases may be pulled straight and large drags may crumple it.</source>
        <translation>頂点のドラッグや回転の間、シートは伸びることがあります。可展面のままで展開図が変わり、曲がった折り線はまっすぐに引き伸ばされることがあり、大きなドラッグではしわになることがあります。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="212"/>
        <source>Motion &amp;Axis</source>
        <translation>移動の軸(&amp;A)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="224"/>
        <source>&amp;Free</source>
        <translation>自由(&amp;F)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="225"/>
        <source>Free motion: the Drag tool moves vertices in the view plane; the Rotate tool turns them about the vertical axis (Z), or about the view axis if Tools ▸ Motion Axis ▸ Rotate About the View Axis is on.</source>
        <translation>自由な移動: ドラッグツールは頂点を視平面内で動かし、回転ツールは鉛直軸 (Z) の周り、または ツール ▸ 移動の軸 ▸ 視線軸の周りに回転 がオンのときは視線軸の周りに回転させます。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="228"/>
        <source>&amp;X Axis</source>
        <translation>X 軸(&amp;X)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="229"/>
        <source>X axis: the Drag tool moves vertices along X only; the Rotate tool turns them about an X-parallel axis through their centroid. Holding Y or Z overrides.</source>
        <translation>X 軸: ドラッグツールは頂点を X 方向にだけ動かし、回転ツールは重心を通る X に平行な軸の周りに回転させます。Y または Z を押し続けるとそちらが優先されます。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="231"/>
        <source>&amp;Y Axis</source>
        <translation>Y 軸(&amp;Y)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="232"/>
        <source>Y axis: the Drag tool moves vertices along Y only; the Rotate tool turns them about a Y-parallel axis through their centroid. Holding X or Z overrides.</source>
        <translation>Y 軸: ドラッグツールは頂点を Y 方向にだけ動かし、回転ツールは重心を通る Y に平行な軸の周りに回転させます。X または Z を押し続けるとそちらが優先されます。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="234"/>
        <source>&amp;Z Axis</source>
        <translation>Z 軸(&amp;Z)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="235"/>
        <source>Z axis: the Drag tool moves vertices along Z only; the Rotate tool turns them about a Z-parallel axis through their centroid. Holding X or Y overrides.</source>
        <translation>Z 軸: ドラッグツールは頂点を Z 方向にだけ動かし、回転ツールは重心を通る Z に平行な軸の周りに回転させます。X または Y を押し続けるとそちらが優先されます。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="259"/>
        <source>Rotate About the &amp;View Axis</source>
        <translation>視線軸の周りに回転(&amp;V)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="262"/>
        <source>With the axis choice Free, the Rotate tool turns the vertices about the viewing direction through their centroid instead of the vertical axis.</source>
        <translation>軸が「自由」のとき、回転ツールは頂点を鉛直軸ではなく重心を通る視線方向の周りに回転させます。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="276"/>
        <source>Colour &amp;By</source>
        <translation>色分け(&amp;B)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="284"/>
        <source>&amp;Patch</source>
        <translation>パッチ(&amp;P)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="284"/>
        <source>&amp;Developability</source>
        <translation>可展性(&amp;D)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="284"/>
        <source>&amp;Flatness</source>
        <translation>平面性(&amp;F)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="285"/>
        <source>&amp;Angle Defect</source>
        <translation>角度欠損(&amp;A)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="287"/>
        <source>Every patch in its own colour.</source>
        <translation>パッチごとに色分けします。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="288"/>
        <source>How far every sampled strip quad is from developable: the normalised |det(a−b, a′, b′)|, on a logarithmic scale.</source>
        <translation>サンプルした各帯の四角形が可展からどれだけ離れているか: 正規化した |det(a−b, a′, b′)| を対数スケールで表示します。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="290"/>
        <source>Flatness δ of every sampled quad: the distance of its diagonals over the mean of its two shortest edges, on a logarithmic scale.</source>
        <translation>サンプルした各四角形の平面性 δ: 対角線間の距離を最も短い 2 辺の平均で割った値を対数スケールで表示します。</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_solver.cpp" line="292"/>
        <source>Angle defect |K| = |2π − Σ angles| at the interior vertices of the sampled mesh, in radians, on a logarithmic scale.</source>
        <translation>サンプルしたメッシュの内部頂点での角度欠損 |K| = |2π − Σ 角度| (ラジアン) を対数スケールで表示します。</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ManualWindow</name>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="56"/>
        <source>DevSurf User Manual</source>
        <translation>DevSurf ユーザーマニュアル</translation>
    </message>
</context>
<context>
    <name>devsurf::app::MarkRegionTool</name>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="92"/>
        <source>Mark a region of the reference shape: drag a lasso around it in the 3D view (Shift adds to the mark, a click clears it, Esc leaves the tool), then Enter adds a flat strip over it (L).</source>
        <translation>参照形状の領域をマーク: 3D ビューで投げ縄で囲み (Shift でマークに追加、クリックでマークを消去、Esc でツールを終了)、Enter でその上に平らなストリップを追加します (L)。</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="95"/>
        <source>Mark a region of the reference shape with a lasso: import one first (File ▸ Import Reference Shape…).</source>
        <translation>参照形状の領域を投げ縄でマーク: まず読み込んでください (ファイル ▸ 参照形状を読み込む…)。</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="102"/>
        <source>Add a flat strip fitted to the marked points (their PCA plane), one undo step; Tools ▸ Approximate Reference Shape… with the design&apos;s surfaces then pulls it onto the shape.</source>
        <translation>マークした点に当てはめた平らなストリップ (PCA 平面) を追加します (元に戻す 1 段階)。その後 ツール ▸ 参照形状を近似… でデザインの曲面を選ぶと形状に引き寄せられます。</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="105"/>
        <source>Add a flat strip over a marked region of the reference shape: mark one first (Tools ▸ Mark Region of Reference Shape).</source>
        <translation>参照形状のマークした領域に平らなストリップを追加: まず領域をマークしてください (ツール ▸ 参照形状の領域をマーク)。</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="117"/>
        <source>Mark region: drag a lasso around part of the reference shape in the 3D view; Shift adds to the mark, Enter adds a strip over it, Esc leaves the tool.</source>
        <translation>領域をマーク: 3D ビューで参照形状の一部を投げ縄で囲んでください。Shift でマークに追加、Enter でその上にストリップを追加、Esc でツールを終了します。</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="166"/>
        <source>Lasso dropped; the mark is as it was.</source>
        <translation>投げ縄を破棄しました。マークは元のままです。</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="234"/>
        <source>Mark cleared.</source>
        <translation>マークを消去しました。</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="239"/>
        <source>The reference shapes are hidden: show them (View ▸ Reference Shapes) to mark a region.</source>
        <translation>参照形状が非表示です: 領域をマークするには表示してください (表示 ▸ 参照形状)。</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="260"/>
        <source>No point of the reference shape facing the camera lies inside the lasso; nothing is marked.</source>
        <translation>カメラの方を向いた参照形状の点が投げ縄の内側にありません。何もマークされていません。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/mark_region_tool.cpp" line="274"/>
        <source>%Ln point(s) of %1 marked.</source>
        <translation>
            <numerusform>%1 の %Ln 点をマークしました。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/mark_region_tool.cpp" line="276"/>
        <source>%Ln point(s) of the reference shapes marked.</source>
        <translation>
            <numerusform>参照形状の %Ln 点をマークしました。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="278"/>
        <source>%1 Enter adds a strip over them; Shift and a lasso add to the mark.</source>
        <translation>%1 Enter でその上にストリップを追加、Shift を押しながら囲むとマークに追加します。</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="297"/>
        <source>No region is marked: draw a lasso around part of the reference shape first (Tools ▸ Mark Region of Reference Shape).</source>
        <translation>領域がマークされていません: まず参照形状の一部を投げ縄で囲んでください (ツール ▸ 参照形状の領域をマーク)。</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="302"/>
        <source>Too few points are marked for a strip: mark at least three points that do not lie on a line.</source>
        <translation>ストリップには点が少なすぎます: 一直線上にない 3 点以上をマークしてください。</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="310"/>
        <source>The marked points lie on a line, so no plane fits them: mark a region that is wide in two directions.</source>
        <translation>マークした点は一直線上にあるので平面を当てはめられません: 2 方向に広がった領域をマークしてください。</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="319"/>
        <source>Add Strip Over Marked Region</source>
        <translation>マークした領域にストリップを追加</translation>
    </message>
    <message>
        <location filename="../app/gui/mark_region_tool.cpp" line="320"/>
        <source>Cannot add the strip</source>
        <translation>ストリップを追加できません</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/mark_region_tool.cpp" line="325"/>
        <source>Added strip %1 over %Ln marked point(s); Tools ▸ Approximate Reference Shape… with the design&apos;s surfaces pulls it onto the shape.</source>
        <translation>
            <numerusform>マークした %Ln 点の上にストリップ %1 を追加しました。ツール ▸ 参照形状を近似… でデザインの曲面を選ぶと形状に引き寄せられます。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::MeasureTool</name>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="39"/>
        <source>Measure: click two points of the surface in the 3D view.</source>
        <translation>計測: 3D ビューで曲面上の 2 点をクリックしてください。</translation>
    </message>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="48"/>
        <source>Copied: %1</source>
        <translation>コピーしました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="82"/>
        <source>Measure: no surface under the mouse; click on the surface.</source>
        <translation>計測: マウスの下に曲面がありません。曲面上をクリックしてください。</translation>
    </message>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="123"/>
        <source>Edge %1: %2 mm long</source>
        <translation>辺 %1: 長さ %2 mm</translation>
    </message>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="131"/>
        <source>Edges %1 and %2 meet at vertex %3 at %4°</source>
        <translation>辺 %1 と %2 は頂点 %3 で %4° の角度で交わります</translation>
    </message>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="143"/>
        <source>Measured: %1. Ctrl+C copies it.</source>
        <translation>計測: %1。Ctrl+C でコピーできます。</translation>
    </message>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="168"/>
        <source>Measure: first point picked; click the second.</source>
        <translation>計測: 1 点目を選びました。2 点目をクリックしてください。</translation>
    </message>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="187"/>
        <source>3D %1 mm, along the sheet %2 mm</source>
        <translation>3D %1 mm、シートに沿って %2 mm</translation>
    </message>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="188"/>
        <source>3D %1 mm (the points lie on different surfaces)</source>
        <translation>3D %1 mm (2 点は別の曲面上にあります)</translation>
    </message>
    <message>
        <location filename="../app/gui/measure_tool.cpp" line="191"/>
        <source>Distance: %1. Ctrl+C copies it.</source>
        <translation>距離: %1。Ctrl+C でコピーできます。</translation>
    </message>
</context>
<context>
    <name>devsurf::app::MoveDialog</name>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="43"/>
        <source>&amp;Translate</source>
        <translation>平行移動(&amp;T)</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="44"/>
        <source>&amp;Rotate</source>
        <translation>回転(&amp;R)</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="45"/>
        <source>&amp;Keep developable</source>
        <translation>可展を保つ(&amp;K)</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="46"/>
        <source>Move or Rotate Vertices</source>
        <translation>頂点の移動・回転</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="52"/>
        <source>Translation</source>
        <translation>平行移動</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="55"/>
        <source>Offset (x, y, z):</source>
        <translation>移動量 (x, y, z):</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="58"/>
        <source>Rotation</source>
        <translation>回転</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="61"/>
        <source>Axis through (x, y, z):</source>
        <translation>回転軸の通る点 (x, y, z):</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="63"/>
        <source>Axis direction:</source>
        <translation>回転軸の方向:</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="68"/>
        <source>Angle:</source>
        <translation>角度:</translation>
    </message>
    <message>
        <location filename="../app/gui/move_dialog.cpp" line="76"/>
        <source>After the motion, run 10 solver iterations with the moved vertices held at their new positions and the pinned vertices where they are, so that the surface stays developable. The motion and the solve are one undo step; Esc cancels the solve and nothing moves. Off: only the exact motion.</source>
        <translation>移動の後、動かした頂点を新しい位置に、固定した頂点をその場所に保ったままソルバーを 10 回反復し、曲面を可展に保ちます。移動とソルブは 1 回の元に戻す操作になります。Esc でソルブを取り消すと何も動きません。オフ: 正確な移動のみ。</translation>
    </message>
</context>
<context>
    <name>devsurf::app::MoveVerticesReaction</name>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="382"/>
        <source>Translate or rotate the selected vertices with their neighbouring control points. Select vertices of one surface first.</source>
        <translation>選択した頂点を隣接する制御点とともに平行移動または回転します。先に 1 つの曲面の頂点を選択してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="410"/>
        <source>Cannot rotate</source>
        <translation>回転できません</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="410"/>
        <source>Cannot move</source>
        <translation>移動できません</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="419"/>
        <source>the vertices are moved</source>
        <translation>頂点が移動されます</translation>
    </message>
</context>
<context>
    <name>devsurf::app::OpenReaction</name>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="34"/>
        <source>Open Project</source>
        <translation>プロジェクトを開く</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="36"/>
        <source>DevSurf projects (*.devsurf)</source>
        <translation>DevSurf プロジェクト (*.devsurf)</translation>
    </message>
</context>
<context>
    <name>devsurf::app::OpenRecentReaction</name>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="64"/>
        <source>No recent files</source>
        <translation>最近使ったファイルはありません</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/file_reactions.cpp" line="68"/>
        <source>Clear Recent Files</source>
        <translation>最近使ったファイルの一覧を消去</translation>
    </message>
</context>
<context>
    <name>devsurf::app::PatchTreeModel</name>
    <message numerus="yes">
        <location filename="../app/gui/panels/patch_tree_model.cpp" line="120"/>
        <source>%n patch(es)</source>
        <translation>
            <numerusform>パッチ %n 個</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/panels/patch_tree_model.cpp" line="129"/>
        <source>Patch %1</source>
        <translation>パッチ %1</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/patch_tree_model.cpp" line="133"/>
        <source>invalid labelling %1</source>
        <translation>無効なラベル付け %1</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/patch_tree_model.cpp" line="142"/>
        <source>Edge labels along the patch: %1</source>
        <translation>パッチに沿った辺のラベル: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/patch_tree_model.cpp" line="152"/>
        <source>Patch</source>
        <translation>パッチ</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/patch_tree_model.cpp" line="152"/>
        <source>Type</source>
        <translation>種類</translation>
    </message>
</context>
<context>
    <name>devsurf::app::PatternExportDialog</name>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="84"/>
        <source>DXF drawing (*.dxf)</source>
        <translation>DXF 図面 (*.dxf)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="86"/>
        <source>SVG image (*.svg)</source>
        <translation>SVG 画像 (*.svg)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="88"/>
        <source>PDF document (*.pdf)</source>
        <translation>PDF 文書 (*.pdf)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="90"/>
        <source>FOLD crease pattern (*.fold)</source>
        <translation>FOLD 折り線図 (*.fold)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="98"/>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="345"/>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="353"/>
        <source>Export Cutting Pattern</source>
        <translation>型紙のエクスポート</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="102"/>
        <source>DXF (laser and plotter cutters)</source>
        <translation>DXF (レーザー・プロッターカッター用)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="102"/>
        <source>SVG (vinyl and paper cutters)</source>
        <translation>SVG (カッティングマシン用)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="103"/>
        <source>PDF (print at 1:1, tiled)</source>
        <translation>PDF (原寸で印刷、分割)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="103"/>
        <source>FOLD (origami simulators)</source>
        <translation>FOLD (折り紙シミュレーター用)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="104"/>
        <source>&amp;Format:</source>
        <translation>形式(&amp;F):</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="106"/>
        <source>&amp;Polylines</source>
        <translation>ポリライン(&amp;P)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="107"/>
        <source>S&amp;plines</source>
        <translation>スプライン(&amp;P)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="114"/>
        <source>DXF &amp;R12 (for old cutter software)</source>
        <translation>DXF &amp;R12 (古いカッターソフト用)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="116"/>
        <source>Curves:</source>
        <translation>曲線:</translation>
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
        <translation>許容誤差(&amp;T):</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="126"/>
        <source>Cut</source>
        <translation>切断</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="126"/>
        <source>Mountain</source>
        <translation>山折り</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="126"/>
        <source>Valley</source>
        <translation>谷折り</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="127"/>
        <source>Crease</source>
        <translation>折り線</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="127"/>
        <source>Rulings (score)</source>
        <translation>母線 (筋付け)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="127"/>
        <source>Seam</source>
        <translation>継ぎ目</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="128"/>
        <source>Labels</source>
        <translation>ラベル</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="136"/>
        <source>Layers:</source>
        <translation>レイヤー:</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="141"/>
        <source>as &amp;glue tabs</source>
        <translation>のりしろとして(&amp;G)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="146"/>
        <source>&amp;Seam allowance:</source>
        <translation>縫い代(&amp;S):</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="166"/>
        <source>S&amp;heet:</source>
        <translation>シート(&amp;H):</translation>
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
        <translation>レター</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="172"/>
        <source>P&amp;aper (PDF):</source>
        <translation>用紙 (PDF)(&amp;A):</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="179"/>
        <source>Piece</source>
        <translation>ピース</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="179"/>
        <source>Sheet</source>
        <translation>シート</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="179"/>
        <source>Size (mm)</source>
        <translation>サイズ (mm)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="180"/>
        <source>Area (mm²)</source>
        <translation>面積 (mm²)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="180"/>
        <source>Isometry error (mm)</source>
        <translation>等長誤差 (mm)</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="181"/>
        <source>Fits sheet</source>
        <translation>シートに収まる</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="181"/>
        <source>Overlaps</source>
        <translation>重なり</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="185"/>
        <source>Fabrication report</source>
        <translation>製作レポート</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="192"/>
        <source>&amp;Export…</source>
        <translation>エクスポート(&amp;E)…</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="303"/>
        <source>itself</source>
        <translation>自身</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="310"/>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="315"/>
        <source>none</source>
        <translation>なし</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="311"/>
        <source>%1 × %2</source>
        <translation>%1 × %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="314"/>
        <source>yes</source>
        <translation>はい</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="314"/>
        <source>no</source>
        <translation>いいえ</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pattern_export_dialog.cpp" line="320"/>
        <source>%n piece(s)</source>
        <translation>
            <numerusform>ピース %n 個</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pattern_export_dialog.cpp" line="321"/>
        <source>%n sheet(s)</source>
        <translation>
            <numerusform>シート %n 枚</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="323"/>
        <source>largest isometry error %1 mm</source>
        <translation>最大等長誤差 %1 mm</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="343"/>
        <source>Some pieces overlap and cannot be cut as laid out. Export anyway?</source>
        <translation>重なっているピースがあり、この配置では切断できません。それでもエクスポートしますか?</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="344"/>
        <source>The pattern has problems (see the report). Export anyway?</source>
        <translation>型紙に問題があります (レポートを参照)。それでもエクスポートしますか?</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="378"/>
        <source>Writing the cutting pattern…</source>
        <translation>型紙を書き出しています…</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="378"/>
        <source>Cancel</source>
        <translation>キャンセル</translation>
    </message>
    <message>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="364"/>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="374"/>
        <location filename="../app/gui/pattern_export_dialog.cpp" line="389"/>
        <source>Export failed</source>
        <translation>エクスポートに失敗しました</translation>
    </message>
</context>
<context>
    <name>devsurf::app::PinVerticesReaction</name>
    <message>
        <location filename="../app/gui/reactions/pin_reactions.cpp" line="51"/>
        <source>Pin the selected vertices: the solver never moves them. Select vertices of one surface first.</source>
        <translation>選択した頂点を固定します。ソルバーはこれらを動かしません。先に 1 つの曲面の頂点を選択してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pin_reactions.cpp" line="53"/>
        <source>Release the selected pinned vertices. Select vertices of one surface first.</source>
        <translation>選択した頂点の固定を解除します。先に 1 つの曲面の頂点を選択してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pin_reactions.cpp" line="58"/>
        <source>Pin the selected vertices: the solver never moves them.</source>
        <translation>選択した頂点を固定します。ソルバーはこれらを動かしません。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pin_reactions.cpp" line="59"/>
        <source>Release the selected pinned vertices.</source>
        <translation>選択した頂点の固定を解除します。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pin_reactions.cpp" line="70"/>
        <source>Cannot pin the vertices</source>
        <translation>頂点を固定できません</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pin_reactions.cpp" line="70"/>
        <source>Cannot unpin the vertices</source>
        <translation>頂点の固定を解除できません</translation>
    </message>
</context>
<context>
    <name>devsurf::app::PinsPanel</name>
    <message>
        <location filename="../app/gui/panels/pins_panel.cpp" line="22"/>
        <source>Unpin</source>
        <translation>固定を解除</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/pins_panel.cpp" line="26"/>
        <source>No vertex is pinned. Select vertices and choose Tools ▸ Pin Vertices (Ctrl+K): the solver then never moves them.</source>
        <translation>固定された頂点はありません。頂点を選択してツール ▸ 頂点を固定 (Ctrl+K) を選ぶと、ソルバーはそれらを動かしません。</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/pins_panel.cpp" line="29"/>
        <source>The pinned vertices: the solver never moves them. Selecting a row selects its vertex in the views.</source>
        <translation>固定された頂点: ソルバーはこれらを動かしません。行を選択するとビューでその頂点が選択されます。</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/pins_panel.cpp" line="32"/>
        <source>Release the selected pinned vertices (one undo step).</source>
        <translation>選択した固定頂点の固定を解除します (元に戻す 1 ステップ)。</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/pins_panel.cpp" line="66"/>
        <source>Vertex %1</source>
        <translation>頂点 %1</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/pins_panel.cpp" line="67"/>
        <source>Surface %1, vertex %2</source>
        <translation>曲面 %1、頂点 %2</translation>
    </message>
</context>
<context>
    <name>devsurf::app::PrintPatternReaction</name>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="109"/>
        <source>Print Cutting Pattern</source>
        <translation>型紙の印刷</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="114"/>
        <source>Printing failed</source>
        <translation>印刷に失敗しました</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="115"/>
        <source>The pages could not be sent to the printer.</source>
        <translation>ページをプリンターに送れませんでした。</translation>
    </message>
</context>
<context>
    <name>devsurf::app::PrintPreviewReaction</name>
    <message>
        <location filename="../app/gui/reactions/pattern_reactions.cpp" line="135"/>
        <source>Print Preview: Cutting Pattern</source>
        <translation>印刷プレビュー: 型紙</translation>
    </message>
</context>
<context>
    <name>devsurf::app::PropertiesPanel</name>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="28"/>
        <source>degree %1, C%2, %3 intervals</source>
        <translation>次数 %1、C%2、区間数 %3</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="39"/>
        <source>A crease between patches %1 (left) and %2 (right); condition: %3.&lt;br&gt;</source>
        <translation>パッチ %1 (左) と %2 (右) の間の折り線。条件: %3。&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="51"/>
        <source>Mountain fold of %1° (up to %2°).</source>
        <translation>山折り %1° (最大 %2°)。</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="55"/>
        <source>Valley fold of %1° (up to %2°).</source>
        <translation>谷折り %1° (最大 %2°)。</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="59"/>
        <source>Not folded.</source>
        <translation>折れていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="80"/>
        <source>&lt;b&gt;Pinned&lt;/b&gt;: the solver never moves this vertex. Tools ▸ Unpin Vertices (Ctrl+Shift+K) releases it.</source>
        <translation>&lt;b&gt;固定&lt;/b&gt;: ソルバーはこの頂点を動かしません。ツール ▸ 頂点の固定を解除 (Ctrl+Shift+K) で解除します。</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="126"/>
        <source>Nothing selected.&lt;br&gt;%1, %2.&lt;br&gt;&lt;i&gt;Click a vertex, edge or patch to select it; Shift-click adds to the selection.&lt;/i&gt;</source>
        <translation>何も選択されていません。&lt;br&gt;%1、%2。&lt;br&gt;&lt;i&gt;頂点・辺・パッチをクリックすると選択されます。Shift+クリックで選択に追加します。&lt;/i&gt;</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/panels/properties_panel.cpp" line="128"/>
        <location filename="../app/gui/panels/properties_panel.cpp" line="138"/>
        <source>%n patch(es)</source>
        <translation>
            <numerusform>パッチ %n 個</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/panels/properties_panel.cpp" line="129"/>
        <source>%n control point(s)</source>
        <translation>
            <numerusform>制御点 %n 個</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="136"/>
        <source>Selected: %1, %2, %3.</source>
        <translation>選択: %1、%2、%3。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/panels/properties_panel.cpp" line="137"/>
        <source>%n vertex(es)</source>
        <translation>
            <numerusform>頂点 %n 個</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/panels/properties_panel.cpp" line="137"/>
        <source>%n edge(s)</source>
        <translation>
            <numerusform>辺 %n 本</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="152"/>
        <source>&lt;b&gt;Vertex %1&lt;/b&gt;</source>
        <translation>&lt;b&gt;頂点 %1&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="164"/>
        <source>&lt;b&gt;Edge %1&lt;/b&gt; from vertex %2 to vertex %3&lt;br&gt;</source>
        <translation>&lt;b&gt;辺 %1&lt;/b&gt; 頂点 %2 から頂点 %3 まで&lt;br&gt;</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/panels/properties_panel.cpp" line="169"/>
        <source>Spline curve (S), %1, %n control point(s).&lt;br&gt;</source>
        <translation>
            <numerusform>スプライン曲線 (S)、%1、制御点 %n 個。&lt;br&gt;</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="175"/>
        <source>A boundary curve of patch %1.</source>
        <translation>パッチ %1 の境界曲線。</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="179"/>
        <source>Ruling (R), a straight segment of length %1 mm.</source>
        <translation>母線 (R)、長さ %1 mm の線分。</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="186"/>
        <source>Smooth between patches %1 and %2: the surface stays smooth across it.</source>
        <translation>パッチ %1 と %2 の間で滑らか: 曲面はこの母線をまたいで滑らかに保たれます。</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="188"/>
        <source>Sharp between patches %1 and %2: the surface may fold along it.</source>
        <translation>パッチ %1 と %2 の間で鋭角: 曲面はこの母線に沿って折れてもかまいません。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/panels/properties_panel.cpp" line="198"/>
        <source>&lt;b&gt;Patch %1&lt;/b&gt;: %2&lt;br&gt;Edge labels along the patch: %3&lt;br&gt;%n corner(s).</source>
        <translation>
            <numerusform>&lt;b&gt;パッチ %1&lt;/b&gt;: %2&lt;br&gt;パッチに沿った辺のラベル: %3&lt;br&gt;角 %n 個。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/panels/properties_panel.cpp" line="237"/>
        <source>Cannot move</source>
        <translation>移動できません</translation>
    </message>
</context>
<context>
    <name>devsurf::app::RefineCurvesReaction</name>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="360"/>
        <source>Double the spline intervals of the selected curve and of all curves joined to it through strips; the shape stays the same. Select one spline edge or strip first.</source>
        <translation>選択した曲線と、ストリップを介してつながるすべての曲線のスプライン区間を 2 倍にします。形状は変わりません。先にスプライン辺またはストリップを 1 つ選択してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="370"/>
        <source>Cannot refine</source>
        <translation>細分化できません</translation>
    </message>
</context>
<context>
    <name>devsurf::app::RelabelEdgeReaction</name>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="123"/>
        <source>Cannot relabel: %1</source>
        <translation>ラベルを変更できません: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="127"/>
        <source>Turn the selected edges from rulings (R) into spline curves (S) or back. Select edges of one surface first.</source>
        <translation>選択した辺を母線 (R) からスプライン曲線 (S) に、またはその逆に変更します。先に 1 つの曲面の辺を選択してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="134"/>
        <source>Cannot relabel</source>
        <translation>ラベルを変更できません</translation>
    </message>
</context>
<context>
    <name>devsurf::app::RemoveReferenceCurvesReaction</name>
    <message>
        <location filename="../app/gui/reactions/curve_reactions.cpp" line="150"/>
        <source>Cannot remove the reference curves</source>
        <translation>参照曲線を削除できません</translation>
    </message>
</context>
<context>
    <name>devsurf::app::RemoveReferenceShapesReaction</name>
    <message>
        <location filename="../app/gui/reactions/reference_shape_reactions.cpp" line="154"/>
        <source>Cannot remove the reference shapes</source>
        <translation>参照形状を削除できません</translation>
    </message>
</context>
<context>
    <name>devsurf::app::RemoveRulingReaction</name>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="298"/>
        <source>Remove the selected ruling between two strips, merging them into one strip whose curves join theirs. Select one ruling between two strips first.</source>
        <translation>2 つのストリップの間の選択した母線を削除し、両方の曲線をつないだ 1 つのストリップに統合します。先に 2 つのストリップの間の母線を 1 本選択してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="312"/>
        <source>Cannot remove the ruling</source>
        <translation>母線を削除できません</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="322"/>
        <source>Ruling %1 removed: its two strips are one strip, the shape unchanged.</source>
        <translation>母線 %1 を削除しました: 2 つのストリップは 1 つになり、形状は変わりません。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="324"/>
        <source>Ruling %1 removed: its two strips are one strip, up to %2 from where they were; Tools ▸ Solve makes it developable again if it is not.</source>
        <translation>母線 %1 を削除しました: 2 つのストリップは 1 つになり、元の位置から最大 %2 離れています。可展でなくなった場合はツール ▸ ソルブで可展に戻せます。</translation>
    </message>
</context>
<context>
    <name>devsurf::app::RotateTool</name>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="29"/>
        <source>Rotate needs two or more vertices that are not pinned: select them, then press on one of them and move the mouse sideways.</source>
        <translation>回転には固定されていない頂点が 2 個以上必要です: それらを選択し、そのうちの 1 つを押してマウスを横に動かしてください。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/rotate_tool.cpp" line="49"/>
        <source>Rotate %n vertices %1: move the mouse sideways, %2° per pixel.</source>
        <translation>
            <numerusform>%n 個の頂点を%1回転: マウスを横に動かします (1 ピクセルあたり %2°)。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="77"/>
        <source>about the X axis through their centroid</source>
        <translation>重心を通る X 軸の周りに</translation>
    </message>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="79"/>
        <source>about the Y axis through their centroid</source>
        <translation>重心を通る Y 軸の周りに</translation>
    </message>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="81"/>
        <source>about the Z axis through their centroid</source>
        <translation>重心を通る Z 軸の周りに</translation>
    </message>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="85"/>
        <source>about the view axis through their centroid</source>
        <translation>重心を通る視線軸の周りに</translation>
    </message>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="86"/>
        <source>about the vertical axis (Z) through their centroid</source>
        <translation>重心を通る鉛直軸 (Z) の周りに</translation>
    </message>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="90"/>
        <source>Rotate tool: select two or more vertices, press on one of them in the 3D view and move the mouse sideways (%1° per pixel). Esc cancels a rotation.</source>
        <translation>回転ツール: 2 個以上の頂点を選択し、3D ビューでそのうちの 1 つを押してマウスを横に動かします (1 ピクセルあたり %1°)。Esc で回転を取り消します。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/rotate_tool.cpp" line="96"/>
        <source>Rotating %n vertices by %1° %2. Release to finish, Esc cancels.</source>
        <translation>
            <numerusform>%n 個の頂点を%2 %1° 回転中。離すと確定、Esc で取り消し。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/rotate_tool.cpp" line="102"/>
        <source>Rotate %n vertices</source>
        <translation>
            <numerusform>%n 個の頂点を回転</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="106"/>
        <source>Rotation cancelled; the design is as it was.</source>
        <translation>回転を取り消しました。デザインは元のままです。</translation>
    </message>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="110"/>
        <source>Rotation stopped: %1 The design is as it was.</source>
        <translation>回転を中止しました: %1 デザインは元のままです。</translation>
    </message>
    <message>
        <location filename="../app/gui/rotate_tool.cpp" line="114"/>
        <source>Rotation stopped: the design changed during the rotation.</source>
        <translation>回転を中止しました: 回転中にデザインが変更されました。</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ShapeExportDialog</name>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="35"/>
        <source>The design has no surface to export.</source>
        <translation>エクスポートする曲面がデザインにありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="37"/>
        <source>Patch %1 of surface %2 cannot be written as an exact surface.</source>
        <translation>曲面 %2 のパッチ %1 を厳密な曲面として書き出せません。</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="42"/>
        <source>The shape could not be translated into this format. Try another format.</source>
        <translation>形状をこの形式に変換できませんでした。別の形式をお試しください。</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="55"/>
        <location filename="../app/gui/shape_export_dialog.cpp" line="130"/>
        <location filename="../app/gui/shape_export_dialog.cpp" line="187"/>
        <location filename="../app/gui/shape_export_dialog.cpp" line="213"/>
        <source>Export 3D Shape</source>
        <translation>3D 形状のエクスポート</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="58"/>
        <source>STEP AP242: exact surfaces</source>
        <translation>STEP AP242: 厳密な曲面</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="58"/>
        <source>STEP AP214: exact surfaces</source>
        <translation>STEP AP214: 厳密な曲面</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="59"/>
        <source>IGES: exact surfaces</source>
        <translation>IGES: 厳密な曲面</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="59"/>
        <source>OBJ mesh: a group per patch</source>
        <translation>OBJ メッシュ: パッチごとに 1 グループ</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="60"/>
        <source>STL mesh (binary)</source>
        <translation>STL メッシュ (バイナリ)</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="60"/>
        <source>PLY mesh (binary)</source>
        <translation>PLY メッシュ (バイナリ)</translation>
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
        <translation>メッシュの三角形が厳密な曲面から離れてよい距離。</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="75"/>
        <source>none (the surface)</source>
        <translation>なし (曲面そのもの)</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="77"/>
        <source>A sheet of this thickness for 3D printing: both sides offset by half of it, the rim closed.</source>
        <translation>3D プリント用にこの厚さの板にします: 両面を半分ずつオフセットし、縁を閉じます。</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="83"/>
        <source>&amp;Format:</source>
        <translation>形式(&amp;F):</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="84"/>
        <source>Chord &amp;tolerance:</source>
        <translation>弦の許容誤差(&amp;T):</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="85"/>
        <source>T&amp;hickness:</source>
        <translation>厚さ(&amp;H):</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="87"/>
        <source>&amp;Export…</source>
        <translation>エクスポート(&amp;E)…</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="120"/>
        <source>A triangle mesh for renderers, slicers and mesh tools; watertight wherever the design is.</source>
        <translation>レンダラー、スライサー、メッシュツール向けの三角形メッシュ。デザインが閉じている所では水密です。</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="122"/>
        <source>Every patch as its exact B-spline surface, sewn into one shell per surface, in millimetres, faces named after their patches.</source>
        <translation>各パッチを厳密な B スプライン曲面として、曲面ごとに 1 つのシェルに縫い合わせ、ミリメートル単位で、面にパッチ名を付けて書き出します。</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="131"/>
        <source>%1 files (*.%2)</source>
        <translation>%1 ファイル (*.%2)</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="141"/>
        <location filename="../app/gui/shape_export_dialog.cpp" line="149"/>
        <location filename="../app/gui/shape_export_dialog.cpp" line="152"/>
        <location filename="../app/gui/shape_export_dialog.cpp" line="154"/>
        <source>Export failed</source>
        <translation>エクスポートに失敗しました</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="160"/>
        <location filename="../app/gui/shape_export_dialog.cpp" line="202"/>
        <source>Writing the 3D shape…</source>
        <translation>3D 形状を書き出しています…</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="160"/>
        <location filename="../app/gui/shape_export_dialog.cpp" line="202"/>
        <source>Cancel</source>
        <translation>キャンセル</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="178"/>
        <source>surface %1, edge %2 (%3 mm apart)</source>
        <translation>曲面 %1、辺 %2 (%3 mm 離れています)</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="184"/>
        <source>faces: %1, shells: %2</source>
        <translation>面: %1、シェル: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="188"/>
        <source>The shape was written, but some patches could not be sewn together and stay apart in the file: %1.</source>
        <translation>形状は書き出されましたが、縫い合わせられなかったパッチがあり、ファイル内で離れたままです: %1。</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="211"/>
        <source>triangles: %1</source>
        <translation>三角形: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/shape_export_dialog.cpp" line="214"/>
        <source>The mesh was written with %1 samples per curve interval, the most DevSurf writes, and is coarser than the tolerance asked for.</source>
        <translation>メッシュは曲線区間あたり %1 サンプル (DevSurf の上限) で書き出され、指定の許容誤差より粗くなっています。</translation>
    </message>
</context>
<context>
    <name>devsurf::app::SheetShapeDialog</name>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="52"/>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="53"/>
        <source>Choose…</source>
        <translation>選択…</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="54"/>
        <source>None</source>
        <translation>なし</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="55"/>
        <source>As They Lie</source>
        <translation>現在の位置で</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="58"/>
        <source>Sheet Shape</source>
        <translation>シートの形</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="61"/>
        <source>Free: the development as it is</source>
        <translation>自由: 展開図をそのまま</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="63"/>
        <source>Rectangle</source>
        <translation>長方形</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="64"/>
        <source>Disk</source>
        <translation>円板</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="65"/>
        <source>Annulus</source>
        <translation>円環</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="66"/>
        <source>Outline of a drawing</source>
        <translation>図面の輪郭</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="77"/>
        <source>The closed curves of a DXF, SVG, STEP or IGES file, seen from above: the largest is the sheet&apos;s boundary, the others its holes.</source>
        <translation>DXF、SVG、STEP または IGES ファイルの閉じた曲線を上から見たもの: 最大のものがシートの境界、ほかは穴です。</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="95"/>
        <source>The sheet the surface is folded from. Every solve and drag keeps the surface isometric to its development; with a shape, the development may change inside it, its boundary on the shape&apos;s and its corners at the shape&apos;s corners.</source>
        <translation>曲面を折り出すシートです。ソルブとドラッグは常に曲面を展開図と等長に保ちます。形を指定すると、展開図はその内側で変わることができ、境界は形の境界上に、角は形の角に置かれます。</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="102"/>
        <source>Shape:</source>
        <translation>形:</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="103"/>
        <source>Width:</source>
        <translation>幅:</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="104"/>
        <source>Height:</source>
        <translation>高さ:</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="105"/>
        <source>Radius:</source>
        <translation>半径:</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="106"/>
        <source>Inner radius:</source>
        <translation>内径:</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="110"/>
        <source>Outline:</source>
        <translation>輪郭:</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="122"/>
        <source>Curves drawn in the sheet for the creases to follow: every curve of a DXF, SVG, STEP or IGES file, seen from above, in the sheet&apos;s frame (a rectangle from its corner at 0,0; circles centred at 0,0; an outline in its own drawing&apos;s coordinates). A crease lying near a curve keeps its development on it.</source>
        <translation>折り線が従うようシートに描いたカーブ: DXF・SVG・STEP・IGES ファイルのすべてのカーブを上から見て、シートの座標系で使います (長方形は角が 0,0、円は中心が 0,0、輪郭はその図面自身の座標)。カーブの近くにある折り線は展開図上でそのカーブに乗ったままになります。</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="127"/>
        <source>No curves: the creases move freely inside the sheet.</source>
        <translation>カーブなし: 折り線はシートの中で自由に動きます。</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="130"/>
        <source>Hold every crease on the curve it lies on in the sheet now: the crease pattern stays as it is while the rulings move in the sheet, so the design folds along its own creases.</source>
        <translation>各折り線を、いまシート上で載っている曲線の上に保持します: 母線がシート内で動いても折り線のパターンはそのままなので、デザインは自身の折り線に沿って折れます。</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="138"/>
        <source>Crease curves:</source>
        <translation>折り線カーブ:</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="149"/>
        <source>Sheet Outline</source>
        <translation>シートの輪郭</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="150"/>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="160"/>
        <source>Drawings (*.dxf *.svg *.step *.stp *.iges *.igs)</source>
        <translation>図面 (*.dxf *.svg *.step *.stp *.iges *.igs)</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="159"/>
        <source>Crease Curves</source>
        <translation>折り線カーブ</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="174"/>
        <source>The surface has no crease to hold.</source>
        <translation>このサーフェスには保持できる折り線がありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="238"/>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="296"/>
        <source>%1 cannot be read as a drawing: choose a DXF, SVG, STEP or IGES file.</source>
        <translation>%1 を図面として読み込めません: DXF、SVG、STEP または IGES ファイルを選んでください。</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="241"/>
        <source>%1 holds no closed curve enclosing an area to be the sheet&apos;s outline.</source>
        <translation>%1 にはシートの輪郭となる、面積を囲む閉じた曲線がありません。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="246"/>
        <source>%1: %n closed curve(s)</source>
        <translation>
            <numerusform>%1: 閉じた曲線 %n 本</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="328"/>
        <source>the creases as they lie: %n curve(s)</source>
        <translation>
            <numerusform>現在の位置の折り線: 曲線 %n 本</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="338"/>
        <source>%1; no crease lies near them (within half its length, no other crease nearer), so they are not used</source>
        <translation>%1。近く (長さの半分以内で、より近い折り線が他にない) にある折り線がないため使用しません</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="73"/>
        <source>none chosen</source>
        <translation>未選択</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="74"/>
        <source>%n closed curve(s)</source>
        <translation>
            <numerusform>閉じた曲線 %n 本</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="298"/>
        <source>%1 holds no curve for the creases to follow.</source>
        <translation>%1 には折り線が従うカーブがありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="322"/>
        <source>none</source>
        <translation>なし</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="325"/>
        <source>%n curve(s)</source>
        <translation>
            <numerusform>%n 本のカーブ</numerusform>
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
        <translation>%1 (形を選んだときのみ使用)</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="345"/>
        <source>%1, holding %n crease(s)</source>
        <translation>
            <numerusform>%1、%n 本の折り線を保持</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="366"/>
        <source>The development covers %1 cm² and is held as it is.</source>
        <translation>展開図の面積は %1 cm² で、そのまま保持されます。</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="373"/>
        <source>Choose a drawing whose closed curves are the sheet&apos;s outline.</source>
        <translation>閉じた曲線がシートの輪郭となる図面を選んでください。</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="382"/>
        <source>The outline has no closed curve enclosing an area.</source>
        <translation>輪郭に面積を囲む閉じた曲線がありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="383"/>
        <source>The inner radius must be smaller than the radius.</source>
        <translation>内径は半径より小さくなければなりません。</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="394"/>
        <source>The development (%1 cm²) is larger than this sheet (%2 cm²): no solve can fold the design from it.</source>
        <translation>展開図 (%1 cm²) がこのシート (%2 cm²) より大きいため、どのソルブでもこのシートから折ることはできません。</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="403"/>
        <source>The development (%1 cm²) fits this sheet (%2 cm²): its boundary lies on the sheet&apos;s.</source>
        <translation>展開図 (%1 cm²) はこのシート (%2 cm²) に合っています: 境界はシートの境界上にあります。</translation>
    </message>
    <message>
        <location filename="../app/gui/sheet_shape_dialog.cpp" line="407"/>
        <source>The development covers %1 cm² of this sheet&apos;s %2 cm²; its boundary is up to %3 mm from the sheet&apos;s, and the next Solve moves it onto the sheet.</source>
        <translation>展開図はこのシートの %2 cm² のうち %1 cm² を占めます。境界はシートの境界から最大 %3 mm 離れており、次のソルブでシート上に移ります。</translation>
    </message>
</context>
<context>
    <name>devsurf::app::SheetShapeReaction</name>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="61"/>
        <source>%1 closes around: it is folded from a cylinder of radius %2 mm, its development read modulo the cylinder&apos;s circumference, and no flat sheet shape applies.</source>
        <translation>%1 は一周して閉じています: 半径 %2 mm の円柱から折られ、展開図は円柱の周長を法として読まれるため、平面のシート形状は適用できません。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="126"/>
        <source>Choose the sheet the surface is folded from: its development as it is, or a rectangle, disk or annulus its development stays inside.</source>
        <translation>曲面を折り出すシートを選びます: 展開図そのまま、または展開図が内側に収まる長方形・円板・円環。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="128"/>
        <source>Choose the sheet of a surface: select something on one surface first.</source>
        <translation>曲面のシートを選ぶには、まず 1 つの曲面上で何かを選択してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="141"/>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="166"/>
        <source>Cannot hold the sheet</source>
        <translation>シートを保持できません</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="182"/>
        <source>Set Sheet Shape</source>
        <translation>シートの形を設定</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="184"/>
        <source>Cannot set the sheet shape</source>
        <translation>シートの形を設定できません</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="189"/>
        <source>The development&apos;s creases are up to %1 mm from their curves, its boundary up to %2 mm from the sheet&apos;s: Solve moves them there.</source>
        <translation>展開図の折り線はカーブから最大 %1 mm、境界はシートの境界から最大 %2 mm 離れています。ソルブでそこへ移ります。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/sheet_reactions.cpp" line="194"/>
        <source>The development&apos;s boundary is up to %1 mm from the sheet&apos;s: Solve moves it onto the sheet.</source>
        <translation>展開図の境界はシートの境界から最大 %1 mm 離れています。ソルブで境界がシート上に移ります。</translation>
    </message>
</context>
<context>
    <name>devsurf::app::ShortcutsDialog</name>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="79"/>
        <source>Keyboard Shortcuts</source>
        <translation>キーボードショートカット</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="81"/>
        <source>Keys</source>
        <translation>キー</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="81"/>
        <source>Command</source>
        <translation>コマンド</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="92"/>
        <source>Click</source>
        <translation>クリック</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="92"/>
        <source>Select a vertex, edge or patch (empty space clears)</source>
        <translation>頂点・辺・パッチを選択 (何もない所で選択解除)</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="93"/>
        <source>Shift+Click</source>
        <translation>Shift+クリック</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="93"/>
        <source>Add to or remove from the selection</source>
        <translation>選択に追加、または選択から除外</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="94"/>
        <source>Ctrl+Drag</source>
        <translation>Ctrl+ドラッグ</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="94"/>
        <source>Select the vertices in a rectangle (with Shift: add them)</source>
        <translation>矩形内の頂点を選択 (Shift 併用で追加)</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="95"/>
        <source>Left drag</source>
        <translation>左ドラッグ</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="95"/>
        <source>3D view: rotate; development view: pan</source>
        <translation>3D ビュー: 回転、展開図ビュー: パン</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="96"/>
        <source>Middle drag</source>
        <translation>中ドラッグ</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="96"/>
        <source>Pan</source>
        <translation>パン</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="97"/>
        <source>Wheel or right drag</source>
        <translation>ホイールまたは右ドラッグ</translation>
    </message>
    <message>
        <location filename="../app/gui/help_dialogs.cpp" line="97"/>
        <source>Zoom</source>
        <translation>ズーム</translation>
    </message>
</context>
<context>
    <name>devsurf::app::SmoothRulingsReaction</name>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="136"/>
        <source>Smooth: the solver keeps the surface smooth across the selected rulings (both patches share the tangent plane).</source>
        <translation>滑らか: ソルバーは選択した母線をまたいで曲面を滑らかに保ちます (両方のパッチが接平面を共有します)。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="138"/>
        <source>Sharp: the surface may fold along the selected rulings.</source>
        <translation>鋭角: 曲面は選択した母線に沿って折れてもかまいません。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="140"/>
        <source>Select rulings between two patches of one surface first.</source>
        <translation>先に 1 つの曲面の 2 つのパッチの間の母線を選択してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="178"/>
        <source>&amp;Smooth Rulings</source>
        <translation>滑らかな母線(&amp;S)</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/crease_reactions.cpp" line="181"/>
        <source>S&amp;harp Rulings</source>
        <translation>鋭角の母線(&amp;H)</translation>
    </message>
</context>
<context>
    <name>devsurf::app::SolveController</name>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="97"/>
        <source>There is nothing to solve.</source>
        <translation>ソルブする対象がありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="121"/>
        <source>%1: there is nothing to solve; nothing changed.</source>
        <translation>%1: ソルブするものがありません。何も変更されていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="194"/>
        <source>%1 cancelled; the design is unchanged.</source>
        <translation>%1 を中止しました。デザインは変更されていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="195"/>
        <source>%1 cancelled: %2; the design is unchanged.</source>
        <translation>%1 を中止しました: %2。デザインは変更されていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="198"/>
        <source>%1 cancelled; nothing moved.</source>
        <translation>%1 を取り消しました。何も動いていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="199"/>
        <source>%1 cancelled: %2; nothing moved.</source>
        <translation>%1 を取り消しました: %2。何も動いていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="201"/>
        <source>Solve cancelled; the design is unchanged.</source>
        <translation>ソルブを中止しました。デザインは変更されていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="202"/>
        <source>Solve cancelled: %1; the design is unchanged.</source>
        <translation>ソルブを中止しました: %1。デザインは変更されていません。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_controller.cpp" line="208"/>
        <source>Check the shape: %n patch(es) fold over onto themselves (%1); undo, or pin or move differently.</source>
        <translation>
            <numerusform>形状を確認してください: %n 個のパッチが自身の上に折り返されています (%1)。元に戻すか、固定や移動の仕方を変えてください。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_controller.cpp" line="215"/>
        <source>Check the shape: the development overlaps itself at %n patch(es) (%1); undo, or pin or move differently.</source>
        <translation>
            <numerusform>形状を確認してください: 展開図が %n 個のパッチで自身と重なっています (%1)。元に戻すか、固定や移動の仕方を変えてください。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="225"/>
        <source>%1 failed: %2 The design is unchanged.</source>
        <translation>%1 に失敗しました: %2 デザインは変更されていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="227"/>
        <source>%1 failed: %2 Nothing moved.</source>
        <translation>%1 に失敗しました: %2 何も動いていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="256"/>
        <source>the design changed</source>
        <translation>デザインが変更されました</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="395"/>
        <source>The sheet held the moved vertices back by up to %1 mm.</source>
        <translation>シートにより、動かした頂点は最大 %1 mm 手前で止まりました。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="23"/>
        <source>it stopped before a degenerate shape</source>
        <translation>退化した形の手前で停止</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="26"/>
        <source>no convergence, residual %1</source>
        <translation>収束せず、残差 %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_report_text.cpp" line="29"/>
        <location filename="../app/gui/solve_report_text.cpp" line="58"/>
        <source>folded over in %n place(s)</source>
        <translation>
            <numerusform>%n 箇所で折り返し</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="32"/>
        <source>a development overlapping itself</source>
        <translation>展開図が自身と重なる</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="35"/>
        <source>collapsed strips</source>
        <translation>帯がつぶれる</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="38"/>
        <source>a shape too degenerate to measure</source>
        <translation>測定できないほど退化した形</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="47"/>
        <source>did not reach the tolerance (residual %1; patch %2 sampled %3 from developable)</source>
        <translation>許容誤差に達せず (残差 %1、パッチ %2 のサンプル値は可展から %3)</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="54"/>
        <source>left its kept sheet by %1 mm</source>
        <translation>保持したシートから %1 mm ずれ</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_report_text.cpp" line="61"/>
        <source>left a development overlapping itself at %n patch(es)</source>
        <translation>
            <numerusform>%n 個のパッチで展開図が自己重複</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="68"/>
        <source>would stretch its sheet by %1 % to lie flat</source>
        <translation>平らに広げるとシートが %1 % 伸びる</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="70"/>
        <source>would not lie flat as one sheet</source>
        <translation>1 枚のシートとして平らに広げられない</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="73"/>
        <source>ended not developable</source>
        <translation>可展でない状態で終了</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="101"/>
        <source>Surface %1</source>
        <translation>曲面 %1</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="106"/>
        <source>The solve was cancelled.</source>
        <translation>ソルブを中止しました。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="109"/>
        <source>%1 cannot be solved: %2</source>
        <translation>%1 は解けません: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="110"/>
        <source>%1 cannot be solved.</source>
        <translation>%1 は解けません。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="114"/>
        <source>The drag target of vertex %1 is not a finite point.</source>
        <translation>頂点 %1 のドラッグ先が有限の点ではありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="115"/>
        <source>The drag target of control point %1 of edge %2 is not a finite point.</source>
        <translation>辺 %2 の制御点 %1 のドラッグ先が有限の点ではありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="121"/>
        <source>%1 could not be solved: the linear system could not be factorised.</source>
        <translation>%1 を解けませんでした: 連立一次方程式を分解できませんでした。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="123"/>
        <source>%1 could not be solved: an iteration gave values that are not finite.</source>
        <translation>%1 を解けませんでした: 反復で有限でない値が生じました。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="127"/>
        <source>%1 could not be solved: the solver produced a value that is not finite.</source>
        <translation>%1 を解けませんでした: ソルバーが有限でない値を出しました。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="133"/>
        <source>(Solver: %1)</source>
        <translation>(ソルバー: %1)</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="151"/>
        <source>Cancelled; the design is unchanged.</source>
        <translation>中止しました。デザインは変更されていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="155"/>
        <source>Failed: %1</source>
        <translation>失敗: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="169"/>
        <source>converged</source>
        <translation>収束</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="173"/>
        <source>tolerance reached</source>
        <translation>許容値に到達</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="176"/>
        <source>stopped after %1 iterations, the residual no longer falling</source>
        <translation>残差が下がらなくなったため %1 回の反復で停止</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="179"/>
        <source>iteration limit reached</source>
        <translation>反復回数の上限に到達</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="187"/>
        <source>failed</source>
        <translation>失敗</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="195"/>
        <source>; left as it was, since solving made it less developable (%1 → %2)</source>
        <translation>。ソルブで可展性が悪化したため元のままにしました (%1 → %2)</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="201"/>
        <source>; settled a second time, since the first settling after the release did not converge</source>
        <translation>; 離した後の最初の反復が収束しなかったため、もう一度収束させました</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="205"/>
        <source>; keeping lengths failed (%1), so the drag was replayed letting the sheet stretch</source>
        <translation>; 長さを保てなかったため (%1)、シートの伸びを許してドラッグをやり直しました</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="214"/>
        <source>followed %1 % of the drag and held back %2 mm, since the whole drag %3: the design stays at its last developable state</source>
        <translation>ドラッグの %1 % まで追従し、%2 mm 手前で止めました (ドラッグ全体の結果: %3)、デザインは最後の可展な状態のままです</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="220"/>
        <source>not applied, since the motion %1: the design stays as it was</source>
        <translation>適用しませんでした (動かした結果: %1)、デザインは元のままです</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="228"/>
        <source>; held back %1 mm by the sheet</source>
        <translation>; シートにより %1 mm 手前で止まりました</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_report_text.cpp" line="243"/>
        <source>; %n patch(es) fold over onto themselves, where the surface overlaps itself: %1</source>
        <translation>
            <numerusform>; %n 個のパッチが自身の上に折り返され、曲面が自己重複しています: %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_report_text.cpp" line="258"/>
        <source>; the development overlaps itself at %n patch(es) (%1) and cannot be cut from one sheet</source>
        <translation>
            <numerusform>; 展開図が %n 個のパッチで自身と重なっており (%1)、1 枚のシートから切り出せません</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="264"/>
        <source>surface %1 %2</source>
        <translation>曲面 %1 %2</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="269"/>
        <source>patch %1: %2</source>
        <translation>パッチ %1: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="274"/>
        <source>nothing was solved.</source>
        <translation>何もソルブされませんでした。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="264"/>
        <source>Solve</source>
        <translation>ソルブ</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="282"/>
        <source>%1 discarded: the design changed meanwhile; it is unchanged.</source>
        <translation>%1 を破棄しました: その間にデザインが変更されました。デザインは変更されていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="323"/>
        <source>Solve left the design as it was: solving made it less developable (largest developability residual %1 → %2).</source>
        <translation>ソルブはデザインを元のままにしました。ソルブで可展性が悪化したためです (最大の可展性残差 %1 → %2)。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="347"/>
        <location filename="../app/gui/solve_controller.cpp" line="392"/>
        <source>%1. %2</source>
        <comment>a verdict, then a sentence</comment>
        <translation>%1。%2</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_controller.cpp" line="351"/>
        <source>%n surface(s) left as they were: solving made them less developable.</source>
        <translation>
            <numerusform>%n 個のサーフェスを元のままにしました。ソルブで可展性が悪化したためです。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="363"/>
        <source>%1 discarded: the design changed while solving; nothing moved.</source>
        <translation>%1 を破棄しました: ソルブ中にデザインが変更されました。何も動いていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="371"/>
        <source>%1 not applied: the motion %2; the design is unchanged.</source>
        <translation>%1 は適用しませんでした (動かした結果: %2)。デザインは変更されていません。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_controller.cpp" line="387"/>
        <source>%1, kept developable: %n iteration(s), largest constraint residual %2.</source>
        <translation>
            <numerusform>%1、可展を維持: %n 回反復、最大の制約残差 %2。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="228"/>
        <location filename="../app/gui/solve_controller.cpp" line="315"/>
        <source>Solve failed: %1 The design is unchanged.</source>
        <translation>ソルブに失敗しました: %1 デザインは変更されていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="92"/>
        <source>Solve is not started while %1 runs; cancel it first (Esc).</source>
        <translation>%1 の実行中はソルブを開始しません。先に中止してください (Esc)。</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="84"/>
        <source>; vertex %1 lies on the straight line between the pinned vertices %2 and %3, which are as far apart as in the flat sheet, so bending cannot move it: the sheet stretched</source>
        <translation>; 頂点 %1 は固定した頂点 %2 と %3 を結ぶ直線上にあり、この 2 点の距離は平らなシートと同じなので、曲げだけでは動かせません。シートは伸ばされました</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="91"/>
        <source>; vertex %1 lies inside the triangle of the pinned vertices %2, %3 and %4, which are as far apart as in the flat sheet, so bending cannot move it: the sheet stretched</source>
        <translation>; 頂点 %1 は固定した頂点 %2、%3、%4 の三角形の内側にあり、これらの距離は平らなシートと同じなので、曲げだけでは動かせません。シートは伸ばされました</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="183"/>
        <source>stopped at the last valid state, before a ruling, curve or patch collapsed</source>
        <translation>母線、曲線またはパッチがつぶれる前の最後の有効な状態で停止</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="191"/>
        <source> (ended on iteration %1, the one with the smallest residual)</source>
        <translation> (残差が最小の反復 %1 で終了)</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_report_text.cpp" line="224"/>
        <source>taken back to where the drag started, since the drag %1: the design stays at its last developable state</source>
        <translation>ドラッグ開始時の状態に戻しました (ドラッグの結果: %1)、デザインは最後の可展な状態のままです</translation>
    </message>
    <message>
        <location filename="../app/gui/solve_controller.cpp" line="292"/>
        <source>Solve result discarded: the design changed while solving.</source>
        <translation>ソルブ中にデザインが変更されたため、結果を破棄しました。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/solve_controller.cpp" line="344"/>
        <source>Solved: %n iteration(s), largest constraint residual %1.</source>
        <translation>
            <numerusform>ソルブ完了: %n 回反復、制約残差の最大値 %1。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>devsurf::app::SolverPanel</name>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="22"/>
        <source>Select Patches to Check</source>
        <translation>確認するパッチを選択</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="75"/>
        <source>No solve yet. Tools ▸ Solve (Ctrl+Return) makes the design developable; the Drag tool keeps it developable while you pull vertices.</source>
        <translation>まだソルブしていません。ツール ▸ ソルブ (Ctrl+Return) でデザインを可展面にします。ドラッグツールは頂点を引っ張る間も可展性を保ちます。</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="36"/>
        <source>Surf.</source>
        <translation>曲面</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="36"/>
        <source>Iter.</source>
        <translation>反復</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="36"/>
        <source>Residual</source>
        <translation>残差</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="36"/>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="37"/>
        <source>Surface</source>
        <translation>曲面</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="37"/>
        <source>Iteration</source>
        <translation>反復</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="38"/>
        <source>Largest constraint residual after the iteration</source>
        <translation>反復後の制約残差の最大値</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="39"/>
        <source>Time of the iteration in milliseconds</source>
        <translation>反復の所要時間 (ミリ秒)</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="50"/>
        <source>Selects the patches the last solve names: the least developable ones and those that fold over onto themselves</source>
        <translation>直前のソルブが挙げたパッチ (可展性の最も低いものと自身の上に折り返されたもの) を選択します</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="111"/>
        <source>No solve of the design as it is now: it was edited, or a step undone or redone, since the last report. Tools ▸ Solve (Ctrl+Return) reports on it.</source>
        <translation>現在の形状はまだソルブしていません: 前回のレポートの後に編集、元に戻す、またはやり直しがありました。ツール ▸ ソルブ (Ctrl+Return) で現在の形状についてレポートします。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/panels/solver_panel.cpp" line="152"/>
        <source>&lt;b&gt;%1&lt;/b&gt;: %2&lt;br&gt;%n iteration(s) in %3 ms.</source>
        <translation>
            <numerusform>&lt;b&gt;%1&lt;/b&gt;: %2&lt;br&gt;%n 回反復、%3 ms。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="176"/>
        <source>&lt;br&gt;Crease conditions, sampled along the creases: largest residual %1.</source>
        <translation>&lt;br&gt;折り線の条件 (折り線に沿ってサンプリング): 最大残差 %1。</translation>
    </message>
    <message>
        <location filename="../app/gui/panels/solver_panel.cpp" line="183"/>
        <source>&lt;br&gt;Least developable patches (normalised residual): %1</source>
        <translation>&lt;br&gt;可展性の最も低いパッチ (正規化残差): %1</translation>
    </message>
</context>
<context>
    <name>devsurf::app::SplitAtRulingReaction</name>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="221"/>
        <source>The curves of this strip have a single spline interval, so a ruling can only be added after refining them (the shape stays the same). Refine now?</source>
        <translation>このストリップの曲線はスプライン区間が 1 つしかないため、母線は細分化した後でなければ追加できません (形状は変わりません)。今すぐ細分化しますか?</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="226"/>
        <source>Cannot refine</source>
        <translation>細分化できません</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="220"/>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="237"/>
        <source>Add Ruling</source>
        <translation>母線を追加</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="201"/>
        <source>Add a ruling across the selected strip and the strips that share its curves. Select one strip or cone patch first.</source>
        <translation>選択したストリップと同じ曲線を共有するストリップを横切る母線を追加します。先にストリップまたは錐面のパッチを 1 つ選択してください。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="238"/>
        <source>Where the new ruling crosses patch %1 and the strips that share its curves (green in the 3D view): per cent of the way along the strip. Rulings can go through the %n breakpoint(s) of the curves; refine the curves (Ctrl+Shift+R) for more.</source>
        <translation>
            <numerusform>新しい母線がパッチ %1 と同じ曲線を共有するストリップを横切る位置 (3D ビューで緑): ストリップに沿った割合 (%)。母線は曲線の %n 個の区切り点を通ることができます。さらに増やすには曲線を細分化してください (Ctrl+Shift+R)。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="269"/>
        <source>Cannot add the ruling</source>
        <translation>母線を追加できません</translation>
    </message>
</context>
<context>
    <name>devsurf::app::SubdivideStripReaction</name>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="146"/>
        <source>Add a crease across the selected strip and the row of strips it belongs to. Select one patch of type strip (SRSR) first.</source>
        <translation>選択したストリップとそれが属するストリップの列を横切る折り線を追加します。先に種類がストリップ (SRSR) のパッチを 1 つ選択してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="157"/>
        <source>Add Crease</source>
        <translation>折り線を追加</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="158"/>
        <source>Where the new crease crosses patch %1 and the strips of its row (green in the 3D view): per cent of the way from one curve of the strip to the other.</source>
        <translation>新しい折り線がパッチ %1 とその列のストリップを横切る位置 (3D ビューで緑): ストリップの一方の曲線からもう一方への割合 (%)。</translation>
    </message>
    <message>
        <location filename="../app/gui/reactions/tool_reactions.cpp" line="187"/>
        <source>Cannot add the crease</source>
        <translation>折り線を追加できません</translation>
    </message>
</context>
<context>
    <name>devsurf::app::Workspace</name>
    <message numerus="yes">
        <location filename="../app/gui/workspace.cpp" line="86"/>
        <source>… and %n more problem(s).</source>
        <translation>
            <numerusform>… ほかに %n 件の問題があります。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="106"/>
        <source>Untitled</source>
        <translation>無題</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="109"/>
        <source>Unsaved changes</source>
        <translation>未保存の変更</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="110"/>
        <source>%1 has unsaved changes. Do you want to save them?</source>
        <translation>%1 には未保存の変更があります。保存しますか?</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="124"/>
        <source>Opened %1</source>
        <translation>%1 を開きました</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="131"/>
        <location filename="../app/gui/workspace.cpp" line="134"/>
        <source>Cannot open file</source>
        <translation>ファイルを開けません</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="148"/>
        <source>Save Project As</source>
        <translation>プロジェクトに名前を付けて保存</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="151"/>
        <source>untitled.devsurf</source>
        <translation>無題.devsurf</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="153"/>
        <source>DevSurf projects (*.devsurf)</source>
        <translation>DevSurf プロジェクト (*.devsurf)</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="167"/>
        <source>Cannot save file</source>
        <translation>ファイルを保存できません</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="174"/>
        <source>Saved %1</source>
        <translation>%1 を保存しました</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="183"/>
        <source>New design from the example “%1”, holding the sheet it starts as</source>
        <translation>例「%1」から、元のシートを保持する新しいデザインを作成しました</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="186"/>
        <source>New design from the example “%1”</source>
        <translation>例「%1」から新しいデザインを作成しました</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="188"/>
        <source>Cannot create the example</source>
        <translation>例を作成できません</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="199"/>
        <source>Recovered unsaved work</source>
        <translation>未保存の作業を復元しました</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="202"/>
        <location filename="../app/gui/workspace.cpp" line="205"/>
        <source>Cannot recover</source>
        <translation>復元できません</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="218"/>
        <source>an untitled design</source>
        <translation>無題のデザイン</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="220"/>
        <source>Recover unsaved work</source>
        <translation>未保存の作業の復元</translation>
    </message>
    <message>
        <location filename="../app/gui/workspace.cpp" line="221"/>
        <source>DevSurf did not close properly last time. Recover the unsaved changes to %1 from %2?</source>
        <translation>前回 DevSurf は正常に終了しませんでした。%1 への未保存の変更を %2 から復元しますか?</translation>
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
        <translation>曲面 %1 は有効でないため表示されません。</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="31"/>
        <source>vertex %1, pinned</source>
        <translation>頂点 %1 (固定)</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="32"/>
        <source>vertex %1</source>
        <translation>頂点 %1</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="41"/>
        <source>edge %1 (R)</source>
        <translation>辺 %1 (R)</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="43"/>
        <source>edge %1 (S, crease)</source>
        <translation>辺 %1 (S、折り線)</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="45"/>
        <source>edge %1 (S, boundary)</source>
        <translation>辺 %1 (S、境界)</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="56"/>
        <source>strip (SRSR)</source>
        <translation>ストリップ (SRSR)</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="59"/>
        <source>pointed strip (SRS)</source>
        <translation>尖ったストリップ (SRS)</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="62"/>
        <source>cone (SRR)</source>
        <translation>錐面 (SRR)</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="65"/>
        <source>planar patch</source>
        <translation>平面パッチ</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="68"/>
        <source>invalid patch</source>
        <translation>無効なパッチ</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="71"/>
        <source>patch %1 (%2)</source>
        <translation>パッチ %1 (%2)</translation>
    </message>
    <message>
        <location filename="../views/scene_view_input.cpp" line="76"/>
        <source>surface %1: %2</source>
        <translation>曲面 %1: %2</translation>
    </message>
    <message>
        <location filename="../views/scene_view_distances.cpp" line="99"/>
        <source>Distance to design
(mm)</source>
        <translation>デザインまでの距離
(mm)</translation>
    </message>
    <message>
        <location filename="../views/scene_view_distances.cpp" line="100"/>
        <source>covered</source>
        <translation>被覆</translation>
    </message>
    <message>
        <location filename="../views/scene_view_distances.cpp" line="102"/>
        <source>Measuring…</source>
        <translation>計測中…</translation>
    </message>
    <message>
        <location filename="../views/scene_view_distances.cpp" line="109"/>
        <source>Updating…</source>
        <translation>更新中…</translation>
    </message>
</context>
<context>
    <name>devsurf::views::ViewOverlay</name>
    <message>
        <location filename="../views/view_overlay.cpp" line="72"/>
        <source>CF</source>
        <comment>badge: curved fold</comment>
        <translation>曲</translation>
    </message>
    <message>
        <location filename="../views/view_overlay.cpp" line="74"/>
        <source>G</source>
        <comment>badge: geodesic</comment>
        <translation>測</translation>
    </message>
    <message>
        <location filename="../views/view_overlay.cpp" line="76"/>
        <source>SU</source>
        <comment>badge: straight when unfolded</comment>
        <translation>直</translation>
    </message>
    <message>
        <location filename="../views/view_overlay.cpp" line="144"/>
        <source>Mountain fold</source>
        <translation>山折り</translation>
    </message>
    <message>
        <location filename="../views/view_overlay.cpp" line="148"/>
        <source>Valley fold</source>
        <translation>谷折り</translation>
    </message>
    <message>
        <location filename="../views/view_overlay.cpp" line="152"/>
        <source>Crease, not folded</source>
        <translation>折れていない折り線</translation>
    </message>
    <message>
        <location filename="../views/view_overlay.cpp" line="162"/>
        <source>Smooth ruling</source>
        <translation>滑らかな母線</translation>
    </message>
    <message>
        <location filename="../views/view_overlay.cpp" line="165"/>
        <source>Sharp ruling</source>
        <translation>鋭角の母線</translation>
    </message>
    <message>
        <location filename="../views/view_overlay.cpp" line="168"/>
        <source>Sheet</source>
        <translation>シート</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="33"/>
        <source>Design developable surfaces and curved-crease origami.</source>
        <translation>可展面と曲線折り折り紙を設計します。</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="37"/>
        <source>A project file to open.</source>
        <translation>開くプロジェクトファイル。</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="40"/>
        <source>Start with a built-in example.</source>
        <translation>組み込みの例で開始します。</translation>
    </message>
</context>
</TS>
