%%matlab file to access data from the RIPV VisualizeService
%%
%% ripvOut.m -- the MATLAB / GNU Octave side of the DataVisServer's file exchange
%% (thesis appendix D, kept faithful; fixed and extended, see docs/datavis.md).
%% Start it in the DataVisServer's work directory; it loops until MATLAB or Octave is
%% shut down, or until a file named stop.dat appears there.
%%   MATLAB:      cd WORKDIR; ripvOut            (or: matlab -batch ripvOut)
%%   GNU Octave:  cd WORKDIR; octave-cli --path MATLABDIR --eval ripvOut
%%   (the DataVisServer does the latter itself with --worker octave)
%%
%% Changes from appendix D:
%%  - data.dat may have any number of columns: 1 column plots against the row number,
%%    2 columns make an x-y line plot, more make one series per extra column;
%%  - '%' comment lines at the top carry the title, axis labels, legend and picture size
%%    ('% title: ...', '% xlabel: ...', '% ylabel: ...', '% legend: a | b', '% size: 800x600');
%%    NaN values are gaps in the lines;
%%  - the figure is invisible and printed with print(h, '-djpeg', ...), so it runs headless;
%%  - the files are removed with delete(), not the shell's rm or del, and BEFORE ok.dat is
%%    written: the service may write the next data.dat as soon as it sees ok.dat;
%%  - a plot that fails writes '0 message' to ok.dat instead of stopping the loop;
%%  - a round the service gave up on (info.dat gone or changed) is dropped quietly;
%%  - '% plot: STYLE' draws as the built-in worker does: 'time' (x is epoch seconds, drawn as
%%    UTC dates), 'depth' (time, depth downwards), 'profile' (y is depth, downwards), 'track'
%%    (x longitude, y latitude in degrees at the right aspect for the latitude, the newest fix
%%    - the last row - circled in red and labelled with '% mark: text'); anything else is 'xy'.

dataFile = 'data.dat';
inputFile = 'info.dat';
okFile = 'ok.dat';
stopFile = 'stop.dat';
isOctave = exist('OCTAVE_VERSION', 'builtin') ~= 0;

if isOctave
  %% headless GNU Octave: gnuplot prints without a display
  warning('off', 'all');
  graphics_toolkit('gnuplot');
end

while (1)
  %%open the data file for reading
  %%block until the file is created
  dfid = fopen(dataFile, 'r');
  disp('1st while')
  while (dfid == -1)
    if exist(stopFile, 'file')
      break;
    end
    %%wait for file to be written to
    pause(0.1);
    dfid = fopen(dataFile, 'r');
  end
  if dfid == -1
    delete(stopFile);
    disp('stop.dat found: ripvOut stops')
    break;
  end
  disp('1st scan')
  %%read the '%' lines at the top: title, axis labels, legend, size
  plotTitle = '';
  xLabel = '';
  yLabel = '';
  legendText = {};
  plotSize = [800 600];
  plotStyle = 'xy';
  markText = '';
  pos = ftell(dfid);
  line = fgetl(dfid);
  while ischar(line)
    t = strtrim(line);
    if ~isempty(t)
      if t(1) ~= '%'
        break;
      end
      tok = regexp(t, '^%+\s*([A-Za-z]+)\s*:(.*)$', 'tokens', 'once');
      if ~isempty(tok)
        value = strtrim(tok{2});
        switch lower(tok{1})
          case 'title'
            plotTitle = value;
          case 'xlabel'
            xLabel = value;
          case 'ylabel'
            yLabel = value;
          case 'legend'
            if any(value == '|')
              legendText = strtrim(regexp(value, '\|', 'split'));
            else
              legendText = strtrim(regexp(value, ',', 'split'));
            end
          case 'size'
            s = sscanf(value, '%dx%d');
            if numel(s) == 2
              plotSize = s';
            end
          case 'plot'
            plotStyle = lower(value);
          case 'mark'
            markText = value;
        end
      end
    end
    pos = ftell(dfid);
    line = fgetl(dfid);
  end
  %%the data file has as many columns as its first data row
  nCols = 0;
  if ischar(line)
    nCols = numel(sscanf(line, '%f'));
  end
  fseek(dfid, pos, 'bof');
  if nCols > 0
    visData = fscanf(dfid, '%f', [nCols inf]);
    %%make the data column vectors
    visData = visData';
  else
    visData = [];
  end
  fclose(dfid);

  %%open the info file for reading
  %%block until the file is created
  fid = fopen(inputFile, 'r');
  disp('2nd while')
  while (fid == -1)
    %%wait for file to be written to
    pause(0.1);
    fid = fopen(inputFile, 'r');
  end
  %%the input file will have the .jpg file name used for
  %%storing the data output in
  outputFile = fgetl(fid);
  fclose(fid);
  if ~ischar(outputFile)
    outputFile = 'ripvOut';
  end
  outputFile = strtrim(outputFile);
  outputName = outputFile;
  if isempty(regexp(outputFile, '\.jpg$', 'once'))
    outputFile = [outputFile '.jpg'];
  end

  status = '1';
  h = [];
  try
    if isempty(visData)
      error('data.dat has no data rows');
    end
    h = figure('visible', 'off', 'Position', [0 0 plotSize]);
    %%lines as wide as the built-in worker's (1.2 px), which also survive the JPEG
    set(h, 'DefaultLineLineWidth', 1.2);
    if nCols == 1
      plot(visData(:, 1));
    elseif any(strcmp(plotStyle, {'time', 'depth'}))
      %%epoch seconds to MATLAB date numbers, shown as UTC dates
      plot(visData(:, 1) / 86400 + datenum(1970, 1, 1), visData(:, 2:end));
      datetick('x', 'keeplimits');
    elseif strcmp(plotStyle, 'track')
      plot(visData(:, 1), visData(:, 2:end), '.-', 'MarkerSize', 8);
    else
      plot(visData(:, 1), visData(:, 2:end));
    end
    if any(strcmp(plotStyle, {'depth', 'profile'}))
      set(gca, 'YDir', 'reverse');
    end
    title(plotTitle, 'Interpreter', 'none');
    xlabel(xLabel, 'Interpreter', 'none');
    ylabel(yLabel, 'Interpreter', 'none');
    if ~isempty(legendText)
      lh = legend(legendText);
      set(lh, 'Interpreter', 'none');
    end
    if strcmp(plotStyle, 'track') && nCols > 1
      %%a graticule at the latitude's aspect: one degree of longitude drawn cos(latitude)
      %%as long as one of latitude; the newest fix (the last row with a position) circled
      %%in red and labelled
      lon = visData(:, 1);
      lat = visData(:, 2);
      fix = find(isfinite(lon) & isfinite(lat));
      if ~isempty(fix)
        k = max(0.01, cos((min(lat(fix)) + max(lat(fix))) / 2 * pi / 180));
        spanX = max(max(lon(fix)) - min(lon(fix)), 1e-4) * 1.2;
        spanY = max(max(lat(fix)) - min(lat(fix)), 1e-4) * 1.2;
        axPos = get(gca, 'Position');
        plotW = axPos(3) * plotSize(1);
        plotH = axPos(4) * plotSize(2);
        if spanX * k / spanY > plotW / plotH
          spanY = spanX * k * plotH / plotW;
        else
          spanX = spanY * plotW / plotH / k;
        end
        cx = (min(lon(fix)) + max(lon(fix))) / 2;
        cy = (min(lat(fix)) + max(lat(fix))) / 2;
        set(gca, 'XLim', [cx - spanX / 2, cx + spanX / 2], 'YLim', [cy - spanY / 2, cy + spanY / 2]);
        last = fix(end);
        if isempty(markText)
          markText = 'newest fix';
        end
        hold on;
        plot(lon(last), lat(last), 'o', 'Color', [1 0 0], 'MarkerFaceColor', [1 0 0], 'MarkerSize', 8, ...
             'LineWidth', 2);
        if lon(last) > cx
          text(lon(last), lat(last), [markText '  '], 'HorizontalAlignment', 'right', ...
               'Color', [0.7 0 0], 'FontWeight', 'bold', 'Interpreter', 'none');
        else
          text(lon(last), lat(last), ['  ' markText], 'HorizontalAlignment', 'left', ...
               'Color', [0.7 0 0], 'FontWeight', 'bold', 'Interpreter', 'none');
        end
        hold off;
      end
    end
    grid on;
    set(h, 'PaperUnits', 'inches', 'PaperPosition', [0 0 plotSize / 100]);
    print(h, '-djpeg', '-r100', outputFile);
  catch err
    status = ['0 ' strrep(err.message, sprintf('\n'), ' ')];
  end
  if ~isempty(h)
    close(h);
  end

  %%if the service gave up on this round (timeout), info.dat is gone or names
  %%another output: drop this picture and touch nothing of the next round
  nowName = '';
  fid = fopen(inputFile, 'r');
  if fid ~= -1
    nowName = fgetl(fid);
    fclose(fid);
    if ~ischar(nowName)
      nowName = '';
    end
    nowName = strtrim(nowName);
  end
  if ~strcmp(nowName, outputName)
    if exist(outputFile, 'file')
      delete(outputFile);
    end
    disp('request abandoned: result dropped')
    continue;
  end

  %%delete the input files first: the service writes the next ones when it sees ok.dat
  delete(dataFile);
  delete(inputFile);
  %%tell the java process that the vis is done
  oid = fopen([okFile '.tmp'], 'w');
  fprintf(oid, '%s\n', status);
  fclose(oid);
  %%rename, so the service never sees a half-written ok.dat
  if isOctave
    rename([okFile '.tmp'], okFile);
  else
    movefile([okFile '.tmp'], okFile, 'f');
  end
end

